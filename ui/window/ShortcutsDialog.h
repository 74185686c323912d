#pragma once
#include <QDialog>
#include <QList>
#include <QPair>

class QTableWidget;

namespace stepdeck::ui {

// Help > Keyboard shortcuts (issue 31): the shortcut of every action of the window, read from
// the actions themselves so that the list cannot go stale, STOP and PANIC first, and the keys
// of the keyboard jog. Non-modal, as every StepDeck dialog.
class ShortcutsDialog : public QDialog
{
    Q_OBJECT
public:
    ShortcutsDialog(QWidget* window, const QString& jogKeys, QWidget* parent = nullptr);

    // Key text -> what it does, in the order shown.
    static QList<QPair<QString, QString>> rows(QWidget* window, const QString& jogKeys);

private:
    QTableWidget* m_table;
};

} // namespace stepdeck::ui
