#pragma once
#include "NanotecHostDrive.h"
#include "NanotecSteps.h"
#include "model/CommandResult.h"
#include <QCoreApplication>
#include <functional>

namespace stepdeck::nanotec {

class NanotecController;
class NanotecExchange;

// Stop and panic on a Nanotec bus: 'S' has no ramp (6.2), so speed-mode runs are lowered to
// the start frequency first; panic is one '#*S' to every drive (1.1), confirmed per drive.
// A positioning run stopped by 'S' may lose steps: its position stays known only where the
// drive's encoder confirms the count (error correction on, 5.9; 'C' and 'I' agree within the
// drive's tolerance 'X', 5.13, 5.16, 5.17), else it is unknown until referenced.
// Neither waits behind queued work: both cancel the bus queue before they send.
class NanotecStop
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::nanotec::NanotecController)

public:
    explicit NanotecStop(NanotecController& controller);

    void stop(RequestId id);
    void panic(RequestId id);
    void reset(RequestId id);
    void sendSafetyStop(std::function<void(bool)> done);
    void abortHostSide(ErrorKind kind, const QString& message);
    bool motionMayBeRunning() const;
    int safetyStopTimeoutMs() const;

private:
    bool mayMove(const HostDrive& d) const; // as far as the host can tell
    // encoderChecked: drives stopped mid-positioning that were referenced; their position is
    // kept where the drive's encoder confirms its count (confirmByEncoder).
    void confirmStopped(RequestId id, QList<Axis> axes, const QString& context,
                        QList<Axis> encoderChecked = {});
    Step confirmByEncoder(Axis axis);

    NanotecController& m_ctl;
    NanotecExchange& m_link;
};

} // namespace stepdeck::nanotec
