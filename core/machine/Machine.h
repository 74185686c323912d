#pragma once
#include "MachineDescription.h"
#include "MotionOwnership.h"
#include "controller/ControllerSession.h"
#include "controller/TargetJogger.h"
#include <QObject>
#include <QSet>
#include <QTimer>
#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace stepdeck::machine {

class MachineReferenceRun;
class MachineSetup;
class MachineSwitchOff;

// How a shown position is known (docs/machines.md): read back or confirmed by a reference
// run, estimated by the host, or unknown until the axis is referenced.
enum class PositionKnowledge { Referenced, Estimated, Unknown };

struct MachineAxisStatus
{
    const MachineAxis* axis = nullptr;
    double position = 0; // the device's step count in the axis' unit
    qint64 steps = 0;    // the controller's count
    PositionKnowledge known = PositionKnowledge::Unknown;
    bool moving = false; // moving, jogging, or motion not known (never shown as idle)
};

// The machine state, the worst over its controllers.
enum class MachineState { Idle, Moving, Fault, Disconnected, LinkLost };

// A machine of one or more controllers (issue 19), in its own units. It owns one
// ControllerSession per controller, each in its own thread as for a single controller, and
// reaches the controllers only through them. Safety across controllers
// (docs/architecture.md): stop and panic are posted to every session before any is waited
// for; a controller whose link is lost or whose part of a move fails gets the others stopped;
// a move is checked as a whole and refused before anything is sent anywhere.
class Machine : public QObject
{
    Q_OBJECT
public:
    explicit Machine(QObject* parent = nullptr);
    ~Machine() override;

    // What every controller's options start from before its own addresses and reset line
    // (the front end's action names, the arrival timeout); takes effect at create().
    void setBaseOptions(const ControllerOptions& options) { m_baseOptions = options; }
    // The first controller runs on this session instead of one of the machine's own: create()
    // creates it, destroy() destroys it (stop flushed, port closed) but never deletes it. For a
    // front end that keeps one session object for its connection bar's link, so that what
    // listens to it stays connected across connects (the window's MachineContext).
    void lendSession(ControllerSession* session) { m_lent = session; }

    // Validates the description and creates a session per controller (links not opened yet).
    bool create(const MachineDescription& description, QString* error);
    void destroy(); // every session stops its controller and closes (ControllerSession)
    const MachineDescription& description() const { return m_description; }
    ControllerSession* session(const QString& controllerId) const;

    void open();
    void close();
    // Both return each controller's request (controller id -> id), so that a caller can wait
    // for the acknowledgements; nothing is awaited here.
    // Both also switch the spindle and the coolant off (switchOffSpindleAndCoolant), as
    // LinuxCNC's abort and emergency stop do (issue 47).
    QMap<QString, RequestId> stop();
    QMap<QString, RequestId> panic();
    // Spindle and coolant off on every connected controller that has them, each controller's
    // once its axes stand (the E-LAB board takes SetSpindleRPM and SetCoolOnOff only at
    // standstill). Ends with spindleAndCoolantOff; a call while one runs starts it anew.
    void switchOffSpindleAndCoolant();
    bool isSwitchingOff() const;

    // Positioning in the axes' units (absolute or relative). Checked as a whole first: every
    // axis known, its controller connected, an absolute target only on a referenced axis,
    // targets within the soft limits. Returns the move's id, or 0 with *refusal saying why
    // (nothing was sent). Each controller gets its part back to back; the move ends with
    // moveFinished once every part has, or fails (the others stopped) when one part fails.
    // kind Feed (a program's G1, after its rate was written to each model's
    // Capabilities::feedRateParameter): each part runs at that rate, as the controller's feed
    // move (relative steps) where Capabilities::feedRateUsesFeedMode, else as a positioning
    // move. A controller that takes no rate (no feedRateParameter) refuses the whole move.
    enum class MoveKind { Positioning, Feed };
    quint64 move(const QMap<QString, double>& units, bool absolute, QString* refusal,
                 MoveKind kind = MoveKind::Positioning, const QObject* owner = nullptr);

    // Jog rates in unit/s per machine axis, one input for every controller involved: the
    // caller renews them while its input is held (each controller's jog lease,
    // ControllerOptions::jogLeaseMs), so a lost input lets every lease run out together and
    // every controller ramps down. Axes not named ramp to zero. Rates above an axis'
    // maxJogSpeed are limited to it. Controllers that jog by targets (laser axes, no stop
    // command) get short targets one after the other (TargetJogger) while the input is
    // renewed; without renewal no further target is sent and the one under way ends by
    // itself. Refused (false, *refusal) for an unknown axis or a controller not connected.
    bool jog(const QMap<QString, double>& unitsPerSecond, QString* refusal);
    void endJog(); // every controller ramps down now; no further jog targets

    // Referencing in the file's order (MachineReference.cpp): the named axes (empty: all)
    // grouped by reference.order, lowest first. A group's axes run together, one reference
    // request per controller with the file's direction per axis (models that choose it
    // themselves get none); the next group starts only after every part of the previous one
    // ended referenced. Returns the run's id, or 0 with *refusal (nothing sent): an unknown
    // axis, a controller not connected or without reference runs, a run already going. Ends
    // with referenceFinished; a failed part stops every controller and names its controller.
    quint64 reference(const QStringList& axes, QString* refusal, const QObject* owner = nullptr);
    bool isReferencing() const;

    MachineAxisStatus axisStatus(const MachineAxis& axis) const;
    MachineState state(QString* controllerId = nullptr) const;

    // Writes each controller's setup from the file on every connect (null before create()).
    MachineSetup* setupWriter() const { return m_setup; }

    // Who runs motion on the machine (MotionOwnership, issue 49 item 4): a program or an MDI
    // line takes it before its check and gives it back at its end, so that one refuses while
    // the other holds it. stop(), panic() and destroy() tell the holder to end its work
    // (abortRequested), after the stop went to every controller.
    // The operator's jog (from its first nonzero rate to endJog()) and reference run (from
    // reference() without an owner to its end) hold the motion themselves ("the axes are being
    // jogged", "a reference run is under way"), so a program does not start beside them and
    // they exclude each other. A holder's own moves and reference runs
    // pass `owner` to move() and reference(); anyone else's are refused while it holds the
    // motion, and so are jogs, unless the holder lends it (a run paused: lendMotion).
    bool claimMotion(const QObject* owner, const QString& what, QString* why = nullptr);
    void releaseMotion(const QObject* owner);
    void lendMotion(const QObject* owner, bool lent) { m_owner.setLent(owner, lent); }
    bool holdsMotion(const QObject* owner) const { return m_owner.isHeldBy(owner); }
    QString motionHolder() const { return m_owner.holder(); } // empty: nobody runs motion
    // The jog input is active (a controller jogged since the last endJog()), also while a held
    // run lent the machine (a run does not go on under it: ProgramRunner::resume).
    bool isJogging() const { return !m_jogSessions.isEmpty(); }

Q_SIGNALS:
    void statusChanged();
    void moveFinished(quint64 id, bool ok, const QString& message);
    // A reference run ended: every axis referenced (ok), or why not.
    void referenceFinished(quint64 id, bool ok, const QString& message);
    // A group of a reference run starts: the machine axes it references.
    void referenceGroupStarted(quint64 id, const QStringList& axes);
    // A controller failed (link lost, a refused or failed part of a move): the others were
    // told to stop. The message names the controller.
    void controllerFailed(const QString& controllerId, const QString& message);
    // A controller that jogs by targets refused the next target (position unknown, a soft
    // limit, an end switch): its jog ended; the message says why.
    void jogRefused(const QString& controllerId, const QString& message);
    // switchOffSpindleAndCoolant() ended: every controller acknowledged (ok), or why not (the
    // message names the controller; the operator must switch it off by hand).
    void spindleAndCoolantOff(bool ok, const QString& message);
    // STOP, PANIC or close: whoever holds the machine's motion (claimMotion) ends its work now
    // -- a program or MDI line aborts, a start being checked never begins. Emitted after the
    // stop was posted to every controller, so nothing the holder does goes ahead of it; once
    // per stop, also when the holder's abort stops the machine again.
    void abortRequested();
    void motionHolderChanged(); // claimed or released
    // A request of one of the machine's controllers ended (a move's part, a parameter write or
    // read, a status read, a switch), after the machine took its part of it: for the executors
    // and the run, which reach the controllers through the machine.
    void requestFinished(const QString& controllerId, const stepdeck::CommandResult& result);

private:
    void requestAbort();
    // Empty when `owner` may move the machine now: it holds the motion, nobody does, or the
    // holder lent it; else why not (the holder's name).
    QString motionRefusal(const QObject* owner) const;
    friend class MachineReferenceRun; // the run reaches the sessions as the machine does
    friend class MachineSwitchOff;    // likewise

    // One controller's share of a move: sent, then (for models whose move request ends when
    // the device accepted it) settling until a fresh status shows its axes at rest.
    struct Part
    {
        ControllerSession* session = nullptr;
        QList<Axis> axes;
        // Where the device's count must end (models that read positions back): a part at rest
        // elsewhere stopped before its target.
        AxisVector expected;
        RequestId request = 0;
        RequestId refresh = 0;  // the status read after the request finished
        bool accepted = false;  // the move request finished well
        bool refreshed = false; // a status newer than the acceptance arrived
        // At rest short of its target in one status read: a second read is asked for before
        // the move is called short (one garbled reply must not end a move that still runs).
        bool confirmingShort = false;
        // Models that report arrival: the controller axes that stopped at their end switch
        // instead (the request's "endSwitch" value).
        QStringList endSwitch;
    };
    struct PendingMove
    {
        quint64 id;
        QList<Part> parts;
    };
    struct StepTargets
    {
        ControllerSession* session;
        AxisVector steps;
    };

    void watch(const QString& controllerId, ControllerSession* session);
    void onLinkState(const QString& controllerId, LinkState state, const QString& reason);
    void onResult(ControllerSession* session, const CommandResult& result);
    void onStatus(ControllerSession* session);
    bool onPartResult(Part& part, const CommandResult& result);
    void finishArrivedMoves();
    void failMovesOf(const ControllerSession* session, const QString& message);
    void stopAllBut(const ControllerSession* failed);
    QString checkMove(const QMap<QString, double>& units, bool absolute, MoveKind kind,
                      QList<StepTargets>* plan) const;
    QString checkAxisTarget(const MachineAxis& axis, double value, bool absolute,
                            qint64* steps) const;
    QString controllerIdOf(const ControllerSession* session) const;
    QString machineAxisName(const ControllerSession* session, Axis axis) const;
    QStringList shortOfTarget(const Part& part) const;
    bool confirmShortStops(PendingMove& move);

    MachineDescription m_description;
    ControllerOptions m_baseOptions;
    std::vector<std::unique_ptr<ControllerSession>> m_sessions; // description's order
    QList<PendingMove> m_moves;
    QSet<ControllerSession*> m_jogSessions; // jogged by the input since its last endJog()
    // Controllers that jog by targets: their jogger, released when the input's lease (the
    // controller's jogLeaseMs) runs out without renewal.
    struct TargetJog
    {
        std::unique_ptr<TargetJogger> jogger;
        std::unique_ptr<QTimer> lease;
    };
    std::map<ControllerSession*, TargetJog> m_targetJogs;
    void jogByTargets(ControllerSession* session, const AxisVelocities& stepsPerS);
    void releaseTargetJogs();
    quint64 m_lastMove = 0;
    std::unique_ptr<MachineReferenceRun> m_references; // the reference run, if any
    std::unique_ptr<MachineSwitchOff> m_switchOff;     // spindle and coolant off after a stop
    MotionOwnership m_owner;
    // What the operator's jog and reference run hold the motion as.
    QObject m_jogToken;
    QObject m_referenceToken;
    bool m_abortRequesting = false;      // abortRequested is being emitted
    MachineSetup* m_setup = nullptr;     // the controllers' setups, written on connect (a child)
    ControllerSession* m_lent = nullptr; // not owned (lendSession)
};

} // namespace stepdeck::machine
