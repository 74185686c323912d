#pragma once
#include <QWidget>

class QToolButton;

namespace stepdeck::ui {

class ElidedLabel;
class StatusMessages;

// The status bar's message line: the newest live message of StatusMessages on one line,
// elided at the width it has (the full text in its tooltip), and the "Messages" button that
// opens the message log, counting the messages logged while the log was not on screen.
// Its size never depends on the message (a wrapping label here once grew the status bar by
// 60-130 px and moved the jog pad under a held pointer, issue 16).
class MessageLine : public QWidget
{
    Q_OBJECT
public:
    explicit MessageLine(StatusMessages* messages, QWidget* parent = nullptr);

    ElidedLabel* label() const { return m_label; }
    QToolButton* logButton() const { return m_button; }
    int unseen() const { return m_unseen; }
    // While the log is on screen, new messages count as seen.
    void setLogOnScreen(bool onScreen);

Q_SIGNALS:
    void logRequested();

private:
    void showCurrent();
    void updateButton();

    StatusMessages* m_messages;
    ElidedLabel* m_label;
    QToolButton* m_button;
    int m_unseen = 0;
    bool m_logOnScreen = false;
};

} // namespace stepdeck::ui
