#pragma once
#include "controller/Controller.h"
#include <QWidget>

class QAction;
class QLabel;
class QPushButton;

namespace stepdeck::ui {

class MachineContext;

// STOP and PANIC, always visible, plus the banner that says what the operator must do next:
// after a panic or a reconnect the positions are lost and the machine must be referenced.
// The buttons trigger the window's actions, whose shortcuts (Esc, F1) work whatever widget
// has the focus.
class SafetyBar : public QWidget
{
    Q_OBJECT
public:
    SafetyBar(MachineContext* context, QAction* stop, QAction* panic, QAction* reference,
              QWidget* parent = nullptr);

    QPushButton* stopButton() const { return m_stop; }
    QPushButton* panicButton() const { return m_panic; }
    QString bannerText() const;
    bool positionsLost() const { return m_positionsLost; }

private:
    void refresh();

    MachineContext* m_context;
    QPushButton* m_stop;
    QPushButton* m_panic;
    QPushButton* m_reference;
    QLabel* m_banner;
    bool m_positionsLost = false;
};

} // namespace stepdeck::ui
