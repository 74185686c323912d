#pragma once
#include <QDateTime>
#include <QMap>
#include <QObject>
#include <QTimer>

namespace stepdeck::ui {

// The status bar's message line (issue 11: nothing claims a state that is stale). Every
// message has an owner -- the cause it reports -- and ends when that cause ends: its owner
// clears or replaces it (a link error when the link is back, a jog refusal when jogging
// works), and every message also expires after its lifetime (default kLifetimeMs), so an
// error from minutes ago is never shown as current. The line shows the newest live message
// with its time (a Layout notice only while no other message is live); every message also
// goes into the log (time-stamped, the newest kLogLimit kept) that the window's message log
// shows, so nothing is lost when a message ends.
class StatusMessages : public QObject
{
    Q_OBJECT
public:
    enum class Owner { General, Link, Controller, Request, Jog, Safety, Setup, Layout };
    enum class Severity { Info, Error };
    static constexpr int kLifetimeMs = 60000;
    static constexpr int kLogLimit = 500;

    struct LogEntry
    {
        QDateTime time;
        Severity severity = Severity::Error;
        QString text;
    };

    explicit StatusMessages(QObject* parent = nullptr);

    void show(Owner owner, const QString& text, Severity severity = Severity::Error,
              int lifetimeMs = kLifetimeMs);
    void clear(Owner owner);
    void clearAll();

    QString currentText() const; // the newest live message, without its time
    // The live message of owner (shown or covered by a newer one); empty without one.
    QString text(Owner owner) const;
    QString currentLine() const; // "HH:mm:ss  text"
    Severity currentSeverity() const;
    // Every message shown, oldest first, at most kLogLimit (the oldest are dropped).
    const QList<LogEntry>& log() const { return m_log; }
    // Messages logged since the start, including those dropped from the log.
    quint64 loggedCount() const { return m_logged; }
    static QString logLine(const LogEntry& entry); // "yyyy-MM-dd HH:mm:ss  text"

Q_SIGNALS:
    void changed();
    void logged(const stepdeck::ui::StatusMessages::LogEntry& entry);

private:
    struct Message
    {
        QString text;
        Severity severity = Severity::Error;
        QDateTime shown;
        QDateTime expires;
        quint64 order = 0;
    };
    const Message* newest() const;
    void expire();

    QMap<Owner, Message> m_messages;
    QList<LogEntry> m_log;
    quint64 m_logged = 0;
    quint64 m_order = 0;
    QTimer m_expiry;
};

} // namespace stepdeck::ui
