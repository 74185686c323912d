#pragma once
#include "messages/StatusMessages.h"
#include <QWidget>

class QPlainTextEdit;

namespace stepdeck::ui {

// The message log: every message the status line showed, with date and time, the newest at
// the bottom, at most StatusMessages::kLogLimit. A page of its own (a dock listed in the View
// menu and opened by the status bar's Messages button), so a message that ended or expired
// can still be read in full.
class MessageLog : public QWidget
{
    Q_OBJECT
public:
    explicit MessageLog(StatusMessages* messages, QWidget* parent = nullptr);

    QPlainTextEdit* view() const { return m_view; }
    QStringList lines() const; // as shown, oldest first

private:
    void append(const StatusMessages::LogEntry& entry);

    QPlainTextEdit* m_view;
};

} // namespace stepdeck::ui
