#pragma once
#include "ElabCtlLine.h"
#include <QCoreApplication>

namespace stepdeck::elab {

// Jog on the E-LAB board ("Befehle im Jogbetrieb"): the core JogRamp produces the rates, this
// sends them as <DC4> (signed 16-bit, clamped). Coalescing: at most one <DC4> waits in the
// queue, and it is built from the newest rates when it is written. The first jog from
// standstill is preceded by the standstill check; an active limit switch does not stop jog.
class ElabCtlJog
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::elab::ElabCtlJog)
public:
    struct Hooks
    {
        std::function<void()> halt;                  // Controller::haltJogImmediately
        std::function<void(const QString&)> refused; // jogRefused
        std::function<bool()> connected;
        // A <DC4> got no usable reply (timeout, garbage): whether the board jogs is unknown.
        std::function<void(const QString&)> uncertain;
    };

    ElabCtlJog(ElabCtlLine& line, Hooks hooks);

    void apply(const AxisVelocities& stepsPerS);
    void reset() { m_queued = m_jogMode = m_awaiting = false; } // stop, panic, reset, link loss
    bool inJogMode() const { return m_jogMode; }
    // The board may be jogging: in jog mode, or a <DC4> is queued or unanswered.
    bool mayRun() const { return m_jogMode || m_queued || m_awaiting; }

private:
    void send(bool continuation);
    void nak();

    ElabCtlLine& m_line;
    Hooks m_hooks;
    Triple<qint16> m_rates{}; // the newest ramp output
    Triple<qint16> m_sent{};  // the rates of the <DC4> on the line
    bool m_queued = false;
    bool m_awaiting = false; // written, reply pending
    bool m_jogMode = false;
};

} // namespace stepdeck::elab
