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
// with its time; the tooltip keeps the recent history, so nothing is lost.
class StatusMessages : public QObject
{
    Q_OBJECT
public:
    enum class Owner { General, Link, Controller, Request, Jog, Safety, Setup };
    enum class Severity { Info, Error };
    static constexpr int kLifetimeMs = 60000;
    static constexpr int kHistory = 12;

    explicit StatusMessages(QObject* parent = nullptr);

    void show(Owner owner, const QString& text, Severity severity = Severity::Error,
              int lifetimeMs = kLifetimeMs);
    void clear(Owner owner);
    void clearAll();

    QString currentText() const; // the newest live message, without its time
    QString currentLine() const; // "HH:mm:ss  text"
    Severity currentSeverity() const;
    QStringList history() const; // newest first, with times

Q_SIGNALS:
    void changed();

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
    QStringList m_history;
    quint64 m_order = 0;
    QTimer m_expiry;
};

} // namespace stepdeck::ui
