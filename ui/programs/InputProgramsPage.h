#pragma once
#include "model/CommandResult.h"
#include <QWidget>

class QLabel;
class QLineEdit;
class QListWidget;
class QPlainTextEdit;
class QPushButton;

namespace stepdeck::ui {

class ElidedLabel;
class MachineContext;

// Programs the controller runs by itself when an input becomes active (Capabilities::
// inputPrograms; EMIS SMC-IC4 manual 9.17): the list of inputs, the selected input's title and
// commands (one per line, checked while typing by the model's grammar), Write and Erase.
// The controller cannot read programs back, so the page keeps what was written from here
// (per model, in the settings) and says so.
class InputProgramsPage : public QWidget
{
    Q_OBJECT
public:
    explicit InputProgramsPage(MachineContext* context, QWidget* parent = nullptr);

    QListWidget* inputList() const { return m_list; }
    QLineEdit* titleEdit() const { return m_title; }
    QPlainTextEdit* commandsEdit() const { return m_commands; }
    QPushButton* writeButton() const { return m_write; }
    QPushButton* forceButton() const { return m_force; }
    QPushButton* eraseButton() const { return m_erase; }
    QString messageText() const;
    QString checkText() const;
    int currentInput() const;

public Q_SLOTS:
    void selectInput(int input);
    // false: nothing sent (invalid commands, not connected). force: the controller's warning
    // about inputs with a reference function was read (manual 5.2.2).
    bool writeProgram(bool force = false);
    void eraseProgram();

private:
    void rebuild();
    void loadDraft(int input);
    void saveDraft();
    QStringList commandLines() const;
    QStringList problems() const;
    void refresh();
    void updateItem(int input);
    void onResult(const CommandResult& result);
    void setMessage(const QString& text, bool error);
    QString settingsKey(int input) const;

    MachineContext* m_context;
    QListWidget* m_list;
    QLineEdit* m_title;
    QPlainTextEdit* m_commands;
    ElidedLabel* m_check;
    QPushButton* m_write;
    QPushButton* m_force;
    QPushButton* m_erase;
    ElidedLabel* m_message;
    RequestId m_pending = 0;
    int m_pendingInput = 0;
    bool m_pendingErase = false;
    bool m_loading = false;
};

} // namespace stepdeck::ui
