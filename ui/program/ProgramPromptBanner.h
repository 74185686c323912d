#pragma once
#include <QWidget>

class QPushButton;

namespace stepdeck::ui {

class ElidedLabel;

// M0's prompt while a program holds at it (issue 20): one line with the prompt and a Resume
// button, never a dialog (the STOP and PANIC buttons stay in reach). Its room is reserved
// whether a prompt is shown or not, so nothing moves when one appears.
class ProgramPromptBanner : public QWidget
{
    Q_OBJECT
public:
    explicit ProgramPromptBanner(QWidget* parent = nullptr);

    // line: the M0's line; prompt: its comment (empty: a general "paused at M0" text).
    void showPrompt(int line, const QString& prompt);
    void clearPrompt();
    bool isShowingPrompt() const { return m_showing; }
    QString text() const;
    QPushButton* resumeButton() const { return m_resume; }

Q_SIGNALS:
    void resumeRequested();

private:
    ElidedLabel* m_text;
    QPushButton* m_resume;
    bool m_showing = false;
};

} // namespace stepdeck::ui
