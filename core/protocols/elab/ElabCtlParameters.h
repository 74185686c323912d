#pragma once
#include "model/ParameterSchema.h"
#include <QByteArray>
#include <QCoreApplication>

namespace stepdeck::elab {

// One E-LAB setup command of a parameter write.
struct ElabParameterWrite
{
    QString name;         // schema name, e.g. "start-speed"
    ParameterValue value; // complete: per-axis parameters carry X, Y and Z
    QByteArray frame;     // <ESC>S..., <FS>..., <SO>..., <STX>..., ...
};

// Turns a parameter set into E-LAB setup commands. Pure: validation and encoding only.
//
// Everything is checked before anything is sent: the schema (names, types, ranges), complete
// per-axis values (axes not given take the last written value; refused if none is known), and
// the manual's rule of SetFeedSpeed: feed speed below start speed, because feed mode has no
// ramp. The rule uses values of the same set first, then the last written ones; a feed speed
// whose start speed was never written is refused.
//
// Commands are ordered as the manual lists the setup: <ESC>S, <ESC>M, <ESC>A, <FS>, <SO>,
// <DLE>, <STX>, <SOH>, <SI>.
class ElabCtlParameters
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::elab::ElabCtlParameters)
public:
    // Returns an empty string and fills *plan, or a sentence naming the parameter and why.
    static QString plan(const ParameterSchema& schema, const ParameterSet& set,
                        const ParameterSet& lastWritten, QList<ElabParameterWrite>* plan);
    // The manual's setup order of the parameter names.
    static const QStringList& order();
    // "write Start speed, Max speed and Acceleration first": the end of the refusals while
    // the board reports tmInvSetup, with the parameters' translated labels.
    static QString setupIncompleteHint();
};

} // namespace stepdeck::elab
