#pragma once
#include "NanotecBus.h"
#include "NanotecSteps.h"
#include "model/Axis.h"
#include <QCoreApplication>

namespace stepdeck::nanotec {

class NanotecController;

// One exchange with the drive of an axis on the bus (one request in flight, per-command
// timeouts: NanotecBus): the drive's address looked up when the step runs, the outcome turned
// into a Failure that names the drive, the read-back that proves a setting, and 'A' whose
// lost echo the status word settles.
class NanotecExchange
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::nanotec::NanotecController)

public:
    explicit NanotecExchange(NanotecController& controller) : m_ctl(controller) {}

    Step exchange(Axis axis, const QByteArray& body, Check check = {},
                  NanotecBus::Priority priority = NanotecBus::Priority::Command, int retries = 0,
                  int timeoutMs = 0);
    // Reads 'Z<cmd>' and fails VerifyFailed unless it equals expected (the drive echoes
    // invalid values and silently ignores them, so only a read-back proves a setting).
    Step expectValue(Axis axis, const QByteArray& cmd, qint64 expected);
    Step setting(Axis axis, const QByteArray& body); // an idempotent setting, retried once
    // Reads 'Z<cmd>' into the held settings (NanotecHeldSettings); never fails.
    Step learnValue(Axis axis, char cmd);
    // The drive of axis is known to hold cmd = value (a read-back showed it, nothing since).
    bool holds(Axis axis, char cmd, qint64 value) const;
    Step startRun(Axis axis); // 'A', its lost echo settled by the status word
    Step wait(int ms);
    Failure outcomeFailure(Axis axis, const QByteArray& body, NanotecBus::Outcome outcome,
                           const Reply& reply);

private:
    NanotecController& m_ctl;
};

} // namespace stepdeck::nanotec
