#pragma once
#include <QWidget>

class QPushButton;

namespace stepdeck::ui {

class ElidedLabel;

// The run's message row of the Program page (issue 20): what the run does now ("pausing: the
// current block finishes first", why it ended), and while a program holds at M0 its prompt,
// highlighted, with a Resume button -- never a dialog (STOP and PANIC stay in reach). One
// line whatever the text (elided, full text in the tooltip); the button's room is reserved
// whether it is shown or not, so nothing moves when a prompt appears.
class ProgramPromptBanner : public QWidget
{
    Q_OBJECT
public:
    explicit ProgramPromptBanner(QWidget* parent = nullptr);

    // line: the M0's line; prompt: its comment (empty: a general "paused at M0" text).
    void showPrompt(int line, const QString& prompt);
    void clearPrompt(); // back to the status text
    // What the run does now; shown whenever no prompt is.
    void setStatus(const QString& text);
    QString statusText() const { return m_status; }
    bool isShowingPrompt() const { return m_showing; }
    QString text() const;
    QPushButton* resumeButton() const { return m_resume; }
    // At an M6 that waits for its touch-off (issue 50 item 4): "Keep Z" beside Resume, where
    // program::ProgramRunner::sameToolResumable() offers going on without a new work Z. Takes
    // no room while hidden (the prompt's text gives it).
    void showKeepZ(bool shown);
    QPushButton* keepZButton() const { return m_keepZ; }

Q_SIGNALS:
    void resumeRequested();
    void keepZRequested();

private:
    ElidedLabel* m_text;
    QPushButton* m_resume;
    QPushButton* m_keepZ;
    QString m_status;
    bool m_showing = false;
};

} // namespace stepdeck::ui
