#include "StatusMessages.h"

namespace stepdeck::ui {

namespace {
QString stamp(const QDateTime& t)
{
    return t.time().toString(QStringLiteral("HH:mm:ss"));
}
} // namespace

StatusMessages::StatusMessages(QObject* parent) : QObject(parent)
{
    m_expiry.setSingleShot(true);
    connect(&m_expiry, &QTimer::timeout, this, &StatusMessages::expire);
}

void StatusMessages::show(Owner owner, const QString& text, Severity severity, int lifetimeMs)
{
    if (text.isEmpty()) {
        clear(owner);
        return;
    }
    const QDateTime now = QDateTime::currentDateTime();
    m_messages.insert(owner,
                      Message{text, severity, now, now.addMSecs(qMax(1, lifetimeMs)), ++m_order});
    m_log.append(LogEntry{now, severity, text});
    ++m_logged;
    while (m_log.size() > kLogLimit)
        m_log.removeFirst();
    expire(); // also re-arms the timer for the next expiry
    Q_EMIT logged(m_log.constLast());
    Q_EMIT changed();
}

void StatusMessages::clear(Owner owner)
{
    if (m_messages.remove(owner)) {
        expire();
        Q_EMIT changed();
    }
}

void StatusMessages::clearAll()
{
    if (m_messages.isEmpty())
        return;
    m_messages.clear();
    Q_EMIT changed();
}

void StatusMessages::expire()
{
    const QDateTime now = QDateTime::currentDateTime();
    bool removed = false;
    QDateTime next;
    for (auto it = m_messages.begin(); it != m_messages.end();) {
        if (it->expires <= now) {
            it = m_messages.erase(it);
            removed = true;
        } else {
            if (!next.isValid() || it->expires < next)
                next = it->expires;
            ++it;
        }
    }
    if (next.isValid())
        m_expiry.start(int(qBound(qint64(1), now.msecsTo(next), qint64(24 * 3600 * 1000))));
    else
        m_expiry.stop();
    if (removed && sender() == &m_expiry)
        Q_EMIT changed();
}

const StatusMessages::Message* StatusMessages::newest() const
{
    // A notice about the window's own layout (a page that scrolls) never covers a message
    // about the machine, however old (a position error, "Stop sent", "Stopped: ..."): it
    // shows when nothing else is live. The log has it at once either way.
    const Message* best = nullptr;
    for (auto it = m_messages.cbegin(); it != m_messages.cend(); ++it) {
        if (it.key() != Owner::Layout && (!best || it->order > best->order))
            best = &*it;
    }
    if (best)
        return best;
    const auto layout = m_messages.constFind(Owner::Layout);
    return layout != m_messages.cend() ? &*layout : nullptr;
}

QString StatusMessages::currentText() const
{
    const Message* m = newest();
    return m ? m->text : QString();
}

QString StatusMessages::text(Owner owner) const
{
    const auto it = m_messages.constFind(owner);
    if (it == m_messages.cend() || it->expires <= QDateTime::currentDateTime())
        return {};
    return it->text;
}

QString StatusMessages::currentLine() const
{
    const Message* m = newest();
    return m ? QStringLiteral("%1  %2").arg(stamp(m->shown), m->text) : QString();
}

StatusMessages::Severity StatusMessages::currentSeverity() const
{
    const Message* m = newest();
    return m ? m->severity : Severity::Info;
}

QString StatusMessages::logLine(const LogEntry& entry)
{
    return QStringLiteral("%1  %2").arg(entry.time.toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")),
                                        entry.text);
}

} // namespace stepdeck::ui
