#pragma once
#include "ProgramBlock.h"
#include "model/Capabilities.h"
#include "model/CommandResult.h"
#include "model/ParameterSchema.h"
#include <QCoreApplication>
#include <QMap>
#include <QSet>

namespace stepdeck::machine {
class Machine;
}

namespace stepdeck::program {

// The rates a program's G1 writes (docs/programs.md "How F maps onto each model"): before a
// G1, each controller of the block gets its model's feed-rate parameter
// (Capabilities::feedRateParameter) in steps/s per axis. Where that parameter is also the
// speed of positioning moves (Capabilities::feedRateSetsRapid: Nanotec o, EMIS #E1), the value
// the device had is read before the first write (when the model can read it back) and written
// back before the next G0 and at the program's end, so G0 keeps running at the fast speed.
// Reaches the controllers only through the machine's sessions; the runner waits for the
// requests it returns before the move is sent.
class ProgramRates
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::program::ProgramRates)
public:
    explicit ProgramRates(machine::Machine* machine) : m_machine(machine) {}

    // The requests to finish before the move of `block` (G0 or G1) is sent; none: send at once.
    // Each id is paired with its controller id.
    QMap<RequestId, QString> before(const ProgramBlock& block);
    // A finished request of before() or restore(): a read keeps the value to put back.
    void onResult(const QString& controllerId, const CommandResult& result);
    // Why G0 `rapid` cannot run at the fast speed: a G1 changed it on a controller that can
    // neither read it back nor knew it (the check refuses such programs first; the adapter may
    // have forgotten it since). Empty: it can.
    QString cannotPutBack(const ProgramBlock& rapid) const;
    // The fast speeds a G1 changed, and the interpolation a coordinated G1 turned on, written
    // back (the program's end); none: nothing to do.
    QMap<RequestId, QString> restore();

private:
    struct Controller
    {
        ParameterValue fast;  // read before the first G1 (perAxis empty: not read)
        RequestId read = 0;   // the read under way
        bool changed = false; // a G1 wrote a rate that G0 would also run at
        // Capabilities::interpolationParameter: written on by this run (before: the value the
        // adapter knew, put back at the end; invalid: not known, left on).
        bool interpolationWritten = false;
        QVariant interpolationBefore;
    };
    // The interpolation write a coordinated G1 of `block` needs on controller `id` (none: the
    // model has no such parameter, fewer than two of its axes move, or it is on already).
    ParameterSet interpolationWrite(const QString& id, const Capabilities& caps,
                                    const ProgramBlock& block, const ParameterSet& known);
    QMap<RequestId, QString> putBack(const QStringList& controllers);

    machine::Machine* m_machine;
    QMap<QString, Controller> m_controllers;
};

} // namespace stepdeck::program
