#pragma once
#include "EmisGrammar.h"
#include "model/CommandResult.h"
#include "model/ParameterSchema.h"

// Parameter sets <-> SMC-IC4 commands: the working values of `set` (9.4-9.12), the system
// parameters of `store` (9.14) and what *PRSYS reports (9.15). Pure: no I/O.
namespace stepdeck::emis {

struct ParameterPlan
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::emis::ParameterPlan)

public:
    struct Frame
    {
        QByteArray bytes;     // the command with its <CR>
        QString parameter;    // the parameter(s) it writes, for messages
        int storedMotors = 0; // "##" writes: the motors the entry names (EmisLink, 9.14)
    };
    QList<Frame> frames;
    ErrorKind error = ErrorKind::None;
    QString message;
    bool ok() const { return error == ErrorKind::None; }
};

// Run and idle current are written together ("c,x100,20", 9.8; "##c,x100,0,...", 9.14): a
// set that names only one of them takes the other from `runKnown` / `idleKnown` (the values
// the adapter knows: written in this session or stored for `set`, stored for `store`), or
// fails with InvalidValue naming what is missing.
struct CurrentPartners
{
    QMap<Axis, qint64> runKnown;
    QMap<Axis, qint64> idleKnown;
};

// The working-value commands for an already validated set, in a fixed order (resolution,
// currents, ramp, speeds, offsets, interpolation, switch type). A per-axis speed equal on all
// four axes is written once for all ("#S200", "#E1,1000"). reference-switch-type has no
// working command: it is written as the system parameter ##REFSW (9.14).
ParameterPlan planWorking(const ParameterSet& set, const CurrentPartners& partners);
// The "##" commands for `store`. Parameters without a system entry (reference-offset,
// interpolation) fail with Unsupported. reference-speed is stored for every motor (##E9).
ParameterPlan planStore(const ParameterSet& set, const CurrentPartners& partners);
// The parameters that have a system entry (9.14), in schema order.
QStringList storableParameters();

// What *PRSYS reported, as parameter values (only what it reported). `notes` says what could
// not be expressed (reference speeds that differ per motor, the SMCflex entry, unparsed text).
ParameterSet storedValues(const SystemParameters& stored, QStringList* notes);

} // namespace stepdeck::emis
