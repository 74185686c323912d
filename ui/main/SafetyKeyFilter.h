#pragma once
#include <QObject>
#include <QPointer>

class QAction;

namespace stepdeck::ui {

// Esc (STOP) and F1 (PANIC) are application shortcuts of the main window, but Qt does not
// deliver a window's shortcuts while a modal dialog or a popup (an open combo box list) has
// the keyboard. This application-wide filter covers exactly those cases, so the keys stop the
// machine whatever is open. Esc still closes the dialog or popup as usual.
class SafetyKeyFilter : public QObject
{
    Q_OBJECT
public:
    SafetyKeyFilter(QAction* stop, QAction* panic, QObject* parent = nullptr);
    ~SafetyKeyFilter() override;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    QPointer<QAction> m_stop;
    QPointer<QAction> m_panic;
};

} // namespace stepdeck::ui
