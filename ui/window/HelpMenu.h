#pragma once
#include <QMenu>
#include <QPointer>

namespace stepdeck::ui {

class JogPanel;

// The window's Help menu (issue 31: it had only About): the documentation, the keyboard
// shortcuts, the command line's usage, About StepDeck and About Qt, each a non-modal box.
class HelpMenu : public QMenu
{
    Q_OBJECT
public:
    HelpMenu(QWidget* window, JogPanel* jog, QWidget* parent = nullptr);

    // stepdeck-cli's usage (app/gui passes it; the ui library does not link the CLI). Without
    // it the Command line entry stays hidden.
    void setCommandLineHelp(const QString& text);
    QAction* documentationAction() const { return m_documentation; }
    QAction* shortcutsAction() const { return m_shortcuts; }
    QAction* commandLineAction() const { return m_commandLine; }

private:
    void showShortcuts();
    void showCommandLine();

    QWidget* m_window;
    QPointer<JogPanel> m_jog;
    QString m_commandLineHelp;
    QAction* m_documentation;
    QAction* m_shortcuts;
    QAction* m_commandLine;
};

} // namespace stepdeck::ui
