#include "ElabCtlJog.h"
#include <QCoreApplication>
#include <limits>

namespace stepdeck::elab {

namespace {} // namespace

ElabCtlJog::ElabCtlJog(ElabCtlLine& line, Hooks hooks) : m_line(line), m_hooks(std::move(hooks)) {}

void ElabCtlJog::apply(const AxisVelocities& stepsPerS)
{
    // SetJogSpeed: "Die Werte sind 16bit Integer mit Vorzeichen."
    for (Axis a : ElabCtlStatusMapper::axes()) {
        const double v = qBound(double(std::numeric_limits<qint16>::min()), stepsPerS.value(a),
                                double(std::numeric_limits<qint16>::max()));
        m_rates[wireIndex(a)] = qint16(qRound(v));
    }
    if (m_queued || !m_hooks.connected())
        return; // the queued <DC4> picks the newest rates up when it is written
    m_queued = true;
    if (m_jogMode || m_rates == Triple<qint16>{}) {
        send(false);
        return;
    }
    // "muss vor dem ersten Jog-Kommando solange mit RequestAxeState gepollt werden, bis der
    // letzte Befehl komplett ausgeführt ist" -- jog stays allowed on an active limit switch.
    const quint64 epoch = m_line.epoch();
    m_line.readStatus(
        0, ElabCtlLine::StatusRead{},
        [this, epoch] {
            if (epoch != m_line.epoch())
                return;
            const QString refusal = ElabCtlStatusMapper::refusal(
                ElabCtlStatusMapper::Rule::FirstJog, m_line.machineWord(), m_line.axeWord());
            if (refusal.isEmpty()) {
                send(true);
                return;
            }
            m_queued = false;
            m_hooks.halt();
            m_line.hooks().publish();
            m_hooks.refused(refusal);
        },
        [this](ErrorKind kind, const QString& why) {
            m_queued = false;
            m_hooks.halt();
            if (kind == ErrorKind::Cancelled)
                return;
            // The status could not be read: a communication fault (the poller decides about
            // the link), not a refusal by the manual's rules.
            m_line.hooks().error(tr("jog not started: %1").arg(why));
        });
}

void ElabCtlJog::send(bool continuation)
{
    ElabExchange ex = ElabCtlLine::exchange(0, {}, Expect::AckNak);
    ex.build = [this] {
        m_queued = false; // from now on a new rate needs a new <DC4>
        m_awaiting = true;
        m_sent = m_rates;
        return encode::jogSpeed(m_rates);
    };
    ex.onReply = [this](const Reply& r) {
        m_awaiting = false;
        if (r.kind == Reply::Kind::Ack) {
            // "Der Modus wird automatisch wieder verlassen, wenn alle 3 Achsen eine Steprate
            // mit dem Wert 0 erhalten."
            m_jogMode = m_sent != Triple<qint16>{};
            return;
        }
        nak();
    };
    ex.onError = [this](ErrorKind kind, const QString& why) {
        const bool written = m_awaiting;
        m_queued = m_awaiting = false;
        if (kind == ErrorKind::Cancelled)
            return;
        m_hooks.halt();
        // The <DC4> may have reached the board (only its reply was lost or garbled): the host
        // no longer knows whether it jogs, so it stops it (zero rates and ForceStopMove) and
        // reads the status instead of assuming standstill.
        if (written && m_hooks.uncertain) {
            m_jogMode = true; // treated as jogging until the zero rates are answered
            m_hooks.uncertain(tr("jog: %1; the board may still be jogging").arg(why));
            return;
        }
        m_jogMode = false;
        m_line.hooks().error(tr("jog: %1").arg(why));
    };
    m_line.submit(std::move(ex), continuation);
}

void ElabCtlJog::nak()
{
    // "kann ein JOG Befehl mit einem <NAK> zurückkehren, wenn der Not-Aus manuell am
    // Controller betätigt wurde": stop the ramp, read both words and say why.
    m_hooks.halt();
    m_jogMode = false;
    ElabCtlLine::StatusRead how;
    how.continuation = true;
    m_line.readStatus(
        0, how,
        [this] {
            const QString why = tr("jog refused by the board (NAK); machine state: %1; axe "
                                   "state: %2")
                                    .arg(describeMachineState(m_line.machineWord()),
                                         describeAxeState(m_line.axeWord()));
            m_line.hooks().error(why);
            m_hooks.refused(why);
        },
        [](ErrorKind, const QString&) {});
}

} // namespace stepdeck::elab
