#pragma once
#include "EmisLink.h"
#include "model/CommandResult.h"
#include <QCoreApplication>
#include <optional>

namespace stepdeck::emis {

// The adapter's side of the SMC-IC4 link: requests onto EmisLink, and what a reply that is not
// <ACK>/<NAK> means as an ErrorKind and a sentence naming the command. While the adapter
// aborts (link lost, closed), the requests it cancels finish with the abort's kind and reason.
class EmisExchange
{
    // Translations stay in the adapter's context (they were written there).
    Q_DECLARE_TR_FUNCTIONS(stepdeck::emis::EmisController)
public:
    using Handler = EmisLink::Handler;

    EmisExchange(Transport* transport, QObject* owner);

    EmisLink& link() { return *m_link; }
    const EmisLink& link() const { return *m_link; }
    void request(const QByteArray& bytes, EmisLink::Expect expect, Handler done, int timeoutMs = 0,
                 int storedMotors = 0, bool exclusive = false);
    // Every pending request finishes Cancelled, reported as `kind` and `message`.
    void cancelAll(ErrorKind kind, const QString& message);
    // The link is exclusive exactly while an input program is being written (9.17).
    bool inputProgramOpen() const { return m_link->isExclusive(); }

    QString failureText(const QByteArray& bytes, const EmisLink::Result& r) const;
    ErrorKind failureKind(const EmisLink::Result& r) const;

private:
    EmisLink* m_link = nullptr; // a child of the adapter: moves to its thread with it
    std::optional<QPair<ErrorKind, QString>> m_abort;
};

} // namespace stepdeck::emis
