#pragma once
#include <QDialog>

class QLabel;
class QPlainTextEdit;

namespace stepdeck::program {
class MachineTools;
}

namespace stepdeck::ui {

// Machine → Tool table…: the machine's tool table as LinuxCNC's tool.tbl text (issue 29,
// docs/programs.md "Tools"), so a table can be typed or pasted from a LinuxCNC machine. Save
// keeps it only when every line reads; otherwise the first error stays on screen (its line and
// column) and nothing changes.
class ToolTableDialog : public QDialog
{
    Q_OBJECT
public:
    ToolTableDialog(program::MachineTools* tools, QWidget* parent = nullptr);

    QPlainTextEdit* editor() const { return m_editor; }
    QString errorText() const;
    bool save(); // as the Save button: true when the table was kept

private:
    // Another machine opened while the dialog is open: its table replaces the text, so that
    // Save never gives one machine's table to another; unsaved edits are said to be dropped.
    void machineChanged();

    program::MachineTools* m_tools;
    QPlainTextEdit* m_editor;
    QLabel* m_error;
};

} // namespace stepdeck::ui
