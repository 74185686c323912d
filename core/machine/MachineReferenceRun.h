#pragma once
#include "MachineDescription.h"
#include "controller/ControllerSession.h"
#include <QElapsedTimer>
#include <optional>

namespace stepdeck::machine {

class Machine;

// The controller direction of an axis' reference run (-1/+1; 1 "reference it" where the model
// chooses the direction itself, Capabilities::referenceDirection false).
int referenceSearchDirection(const MachineAxis& axis, const Capabilities& capabilities);

// A Machine's reference run in the file's order (issue 19, docs/machines.md, "Referencing"):
// the named axes grouped by reference.order, one group after the other, each group's axes
// together with one reference request per controller. The Machine forwards its sessions'
// results and statuses here; the run emits the Machine's referenceFinished,
// referenceGroupStarted and controllerFailed.
class MachineReferenceRun
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::machine::Machine)
public:
    explicit MachineReferenceRun(Machine& machine) : m_machine(machine) {}

    // Empty, or why nothing was started (nothing sent).
    QString start(quint64 id, const QStringList& axes);
    bool isRunning() const { return m_run.has_value(); }
    void onResult(ControllerSession* session, const CommandResult& result);
    void onStatus(ControllerSession* session);
    // Ends a running run as failed; `session` (if any) is the controller that failed, and
    // with stopAll every controller is told to stop.
    void fail(const ControllerSession* session, const QString& message, bool stopAll);

private:
    // One controller's share of a group, done once a status after the accepted request shows
    // its axes referenced and at rest after evidence of the run.
    struct Part
    {
        ControllerSession* session = nullptr;
        QMap<Axis, int> directions;
        RequestId request = 0;
        bool accepted = false;
        bool sawMotion = false;
        bool sawUnreferenced = false;
        bool done = false;
        QElapsedTimer acceptedAt;
    };
    struct Run
    {
        quint64 id = 0;
        QList<QList<const MachineAxis*>> groups; // still to run, the current one first
        QList<Part> parts;                       // the current group's
    };

    QString check(const QStringList& axes, QList<QList<const MachineAxis*>>* groups) const;
    void startGroup();
    bool evaluate(Part& part, QString* failure);
    void finishGroupIfDone();

    Machine& m_machine;
    std::optional<Run> m_run;
};

} // namespace stepdeck::machine
