#pragma once
#include "NanotecBus.h"
#include "NanotecHostDrive.h"
#include "NanotecPollPlan.h"
#include "NanotecSteps.h"
#include "model/CommandResult.h"
#include <QCoreApplication>

namespace stepdeck::nanotec {

class NanotecController;
class NanotecExchange;

// What the host knows of the drives of a Nanotec bus: their initialisation (firmware, caches,
// auto status off), the status sweeps ('$', 'C' and now and then 'ZY' per drive), the auto
// status 'j' (5.31), drives that fall silent, and the normalised MachineStatus.
class NanotecStatus
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::nanotec::NanotecController)

public:
    explicit NanotecStatus(NanotecController& controller);

    // Identifies every drive and fills its caches; finishes the pending open.
    void initialiseDrives();
    void onPollDue();
    void onUnsolicited(const Reply& reply);
    void refreshStatus(RequestId id);
    void applyStatusWord(HostDrive& d, qint64 word);
    void noteAnswer(HostDrive& d, bool answered);
    void updateStatus();
    // Polls at the poller's expedited pace while a positioning or reference run is pending.
    void paceForMotion();
    int pollTimeoutMs() const;
    int sweepBudgetMs() const;

private:
    Step initialiseDrive(Axis axis);
    void finishInitialising();
    // The plan's reads, one drive after the other; the sweep ends with the last.
    void pollDrive(QList<NanotecPollPlan::Read> remaining, std::shared_ptr<bool> answered);
    // Publishes the status at once when no run is pending any more (mid-sweep).
    void publishIfArrived();
    // One poll exchange with the drive of a sweep's axis.
    using PollRequest = std::function<void(const QByteArray& body, NanotecBus::Handler done)>;
    // 'ZY' (5.30); a changed switch input is read twice (noise).
    void readInputs(Axis axis, const PollRequest& request, const std::function<void()>& next);

    NanotecPollPlan m_plan;

    NanotecController& m_ctl;
    NanotecExchange& m_link;
};

} // namespace stepdeck::nanotec
