#pragma once
#include "EmisExchange.h"
#include "EmisHost.h"
#include "EmisParameterPlan.h"

namespace stepdeck::emis {

class EmisMotionTracker;

// The parameters of the SMC-IC4: working values written with `set` (9.4-9.12; the board cannot
// report them, so readParameters() returns those written in this session), and the system
// parameters (store "##" 9.14, *PRSYS 9.15, *PESYS 9.16). Keeps EmisKnownValues up to date.
class EmisParameters
{
    // Translations stay in the adapter's context (they were written there).
    Q_DECLARE_TR_FUNCTIONS(stepdeck::emis::EmisController)
public:
    static constexpr int kStoreTimeoutMs = 3000; // per step of a flash write (##, programs)

    EmisParameters(EmisHost& host, EmisExchange& exchange, EmisKnownValues& known,
                   const EmisMotionTracker& tracker);

    void write(RequestId id, const ParameterSet& values);
    void read(RequestId id, const QStringList& names);
    void store(RequestId id, const QVariantMap& args);
    // *PRSYS; with `after` (the connect sequence) the reply goes there instead of to id.
    void readStored(RequestId id, EmisLink::Handler after = {});
    void clearStored(RequestId id);
    // The console wrote a system entry (##...) or read them (*PRSYS).
    void noteStoredEntry(const SystemEntry& entry);
    void noteStored(const SystemParameters& stored);

private:
    void runFrames(RequestId id, const QList<ParameterPlan::Frame>& frames, int index,
                   std::function<void()> onDone);
    void noteWritten(const ParameterSet& set);
    bool busy() const; // an axis moves, the operator jogs or an input program is written

    EmisHost& m_host;
    EmisExchange& m_exchange;
    EmisKnownValues& m_known;
    const EmisMotionTracker& m_tracker;
    ParameterSet m_written;    // working values written in this session
    SystemParameters m_stored; // the system parameters as last read or written
};

} // namespace stepdeck::emis
