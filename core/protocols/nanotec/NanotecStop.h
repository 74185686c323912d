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
// A stop that arrives while another one is still confirming (a program's abort right behind
// the window's STOP, a failed move part, a second STOP) cancels the older one's exchanges with
// everything else; the older request is then not ended "cancelled" (issue 47 item 7: "'I' to
// drive 1 was cancelled" although the drives stood) but taken over: it ends with the newest
// stop's confirmation, and the encoder check it had to make is made by the newest.
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
    using Finish = std::function<void(const Failure&)>;
    void confirmStopped(Finish finish, QList<Axis> axes, const QString& context,
                        QList<Axis> encoderChecked = {});
    Step confirmByEncoder(Axis axis);
    // Ends every stop request taken over by the stop run `run`, unless a newer run took them.
    void finishStops(quint64 run, const Failure& f);

    NanotecController& m_ctl;
    NanotecExchange& m_link;
    // The stop requests not ended yet (the newest run ends them all), that run, and the drives
    // whose position an encoder check is still to confirm.
    QList<RequestId> m_stopIds;
    quint64 m_stopRun = 0;
    QList<Axis> m_stopEncoderChecked;
};

} // namespace stepdeck::nanotec
