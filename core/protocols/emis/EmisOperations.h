#pragma once
#include "EmisExchange.h"
#include "EmisGrammar.h"
#include "EmisHost.h"

namespace stepdeck::emis {

class EmisMotion;
class EmisMotionTracker;
class EmisParameters;

// The model operations of the SMC-IC4 (EmisController lists their names and arguments):
// outputs (9.3), reference runs of several axes (9.9), input programs (9.17, 9.18); and the
// console, whose commands go through the same bookkeeping as the adapter's own.
class EmisOperations
{
    // Translations stay in the adapter's context (they were written there).
    Q_DECLARE_TR_FUNCTIONS(stepdeck::emis::EmisController)
public:
    EmisOperations(EmisHost& host, EmisExchange& exchange, EmisKnownValues& known,
                   EmisMotionTracker& tracker, EmisMotion& motion, EmisParameters& parameters);

    // False: not an operation of this model (the caller refuses it).
    bool run(RequestId id, const QString& name, const QVariantMap& args);
    void sendRaw(RequestId id, const QByteArray& bytes); // one command of the console

private:
    void setOutput(RequestId id, const QVariantMap& args);
    void referenceOperation(RequestId id, const QVariantMap& args);
    // The commands of a program, checked; empty and *error when one is not valid.
    QList<QByteArray> programLines(const QVariantMap& args, QString* error) const;
    void writeInputProgram(RequestId id, const QVariantMap& args);
    void programStep(RequestId id, int input, const QList<QByteArray>& frames, int index);
    void abortProgram(RequestId id, int input, const QString& why, ErrorKind kind);
    void eraseInputProgram(RequestId id, const QVariantMap& args);
    void sendConsoleCommand(RequestId id, const QByteArray& frame, const Command& c);

    EmisHost& m_host;
    EmisExchange& m_exchange;
    EmisKnownValues& m_known;
    const EmisMotionTracker& m_tracker;
    EmisMotion& m_motion;
    EmisParameters& m_parameters;
};

} // namespace stepdeck::emis
