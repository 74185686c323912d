#include "MessageLog.h"
#include <QLabel>
#include <QPlainTextEdit>
#include <QScrollBar>
#include <QVBoxLayout>

namespace stepdeck::ui {

MessageLog::MessageLog(StatusMessages* messages, QWidget* parent)
    : QWidget(parent), m_view(new QPlainTextEdit(this))
{
    setObjectName(QStringLiteral("messageLog"));
    m_view->setObjectName(QStringLiteral("messageLogView"));
    m_view->setReadOnly(true);
    m_view->setLineWrapMode(QPlainTextEdit::WidgetWidth);
    m_view->setMaximumBlockCount(StatusMessages::kLogLimit); // the oldest lines go first
    m_view->setFocusPolicy(Qt::ClickFocus);
    auto* note = new QLabel(
        tr("Every message of the status line with its time, the newest at the bottom (the "
           "last %1 are kept).")
            .arg(StatusMessages::kLogLimit),
        this);
    note->setStyleSheet(QStringLiteral("QLabel { color: palette(dark); }"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(note);
    layout->addWidget(m_view, 1);
    for (const StatusMessages::LogEntry& entry : messages->log())
        append(entry);
    connect(messages, &StatusMessages::logged, this, &MessageLog::append);
}

QStringList MessageLog::lines() const
{
    return m_view->toPlainText().split(QLatin1Char('\n'), Qt::SkipEmptyParts);
}

void MessageLog::append(const StatusMessages::LogEntry& entry)
{
    QScrollBar* bar = m_view->verticalScrollBar();
    const bool atEnd = bar->value() == bar->maximum();
    // One line per message: a message's own line breaks would split it in the log.
    QString text = StatusMessages::logLine(entry);
    text.replace(QLatin1Char('\n'), QLatin1Char(' '));
    const QString colour = entry.severity == StatusMessages::Severity::Error
                               ? QStringLiteral("#c62828")
                               : m_view->palette().color(QPalette::Text).name();
    m_view->appendHtml(QStringLiteral("<span style=\"color:%1; white-space:pre-wrap\">%2</span>")
                           .arg(colour, text.toHtmlEscaped()));
    if (atEnd)
        bar->setValue(bar->maximum()); // follows the newest unless the operator scrolled up
}

} // namespace stepdeck::ui
