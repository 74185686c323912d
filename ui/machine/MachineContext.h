#pragma once
#include "controller/ControllerSession.h"
#include <QObject>
#include <memory>

namespace stepdeck::machine {
class Machine;
struct MachineDescription;
enum class PositionKnowledge;
} // namespace stepdeck::machine

namespace stepdeck::ui {

class MachineWorkOffsets;

// A model's display name in the current language (context "Models").
QString modelDisplayName(const ModelInfo& model);

// How one axis is shown: user units and the operator's work origin. Host-side only.
struct AxisUnits
{
    double stepsPerUnit = 0; // 0: show steps only
    QString unit = QStringLiteral("mm");
    qint64 workOffset = 0; // steps; work position = machine position - workOffset
};

// The one object every panel shares: the controller session (the only path to the machine),
// the selected model and the operator's display settings. Panels rebuild on modelChanged().
//
// With a machine of several controllers open (issue 19, openMachine()) the context also holds
// the core Machine and a selected controller: session() is the selected controller's session,
// so every per-controller page works on it as on a single controller. Panels connect to
// session() once, when they are built (before any machine is open): that object stays the
// panels' signal source, and with a machine open it relays the selected controller's signals
// (signal-to-signal connections; see relayFrom()). Switching the controller emits
// modelChanged() (panels rebuild) and the new controller's link state and status.
class MachineContext : public QObject
{
    Q_OBJECT
public:
    explicit MachineContext(QObject* parent = nullptr);
    ~MachineContext() override;

    ControllerSession* session() const { return m_selected ? m_selected : m_session; }
    const ModelInfo* model() const { return m_model; }
    Capabilities capabilities() const;
    QList<Axis> axes() const;
    ParameterSchema schema() const;
    QString modelId() const;
    QString portName() const;
    bool isConnected() const;
    const MachineStatus& status() const { return session()->status(); }

    // Chooses the model the panels show before (or without) a connection.
    void selectModel(const QString& modelId);
    // Creates the session of model (a registry entry) for spec and opens the link; false and
    // a reason on failure.
    bool connectTo(const ModelInfo& model, const ConnectionSpec& spec, QString* error);
    void disconnectFromController();

    // Parameter values known to be on the device in this link session: written successfully
    // or read back. Forgotten (knownParametersLost) whenever the device's values may have
    // changed behind the host's back: every (re)connect, link loss, reset, and a board that
    // reports setup incomplete again (power cycle). A write-only controller's form counts
    // nothing as written unless it is in here (issue 11).
    const ParameterSet& knownParameters() const { return m_known; }
    // Session reads and writes that keep knownParameters() up to date: a successful write
    // adds what was written, a read adds what came back.
    RequestId writeParameters(const ParameterSet& values, bool verify);
    RequestId readParameters(const QStringList& names);
    void addKnownParameters(const ParameterSet& set); // merged per axis
    void forgetKnownParameters();

    // Soft limits per axis in machine steps (issue 11), stored per model; the session
    // enforces them in the controller thread for every move and jog.
    SoftLimits softLimits() const { return m_softLimits; }
    void setSoftLimit(Axis axis, const AxisSoftLimit& limit);
    // Machine steps for a work position typed in user units (the inverse of toUserUnits).
    qint64 toMachineSteps(Axis axis, double userValue) const;

    // The single controller's referencing settings (the Referencing panel's, per model): the
    // direction (-1, +1; 0: skip) and the order (lower first; default Z first, then X and Y
    // together, each towards the negative end where most small machines have their switches).
    int referenceDirection(Axis axis) const;
    int referenceOrder(Axis axis) const;
    void setReference(Axis axis, int direction, int order);

    AxisUnits units(Axis axis) const;
    void setUnits(Axis axis, const AxisUnits& units);
    // Machine position in steps -> work position in user units (or steps when none set).
    double toUserUnits(Axis axis, qint64 machineSteps) const;
    QString unitName(Axis axis) const;
    // What the model's machine positions count, translated ("steps"; laser axes: "units"):
    // Capabilities::positionUnit, never a guess from the model id.
    QString machineUnitName() const;

    // The machine (issue 19). openMachine reads and validates the file (MachineFile) and, only
    // if all of it is valid, ends the single-controller link and creates the machine's
    // sessions (links not opened: connectMachine()). False with *error naming the field.
    bool openMachine(const QString& path, QString* error);
    bool openMachine(const machine::MachineDescription& description, QString* error,
                     const QString& path = QString());
    void closeMachine(); // every controller stops and closes; back to a single controller
    // The connected single controller as a machine of one controller (issue 28, item 0): its
    // port, bus addresses and reset line, and each axis in the operator's units (Units…:
    // mm, degrees; inches as mm), with the soft limits set for it, converted; an axis without
    // units stays in steps. workOffsets: its work origins in the axes' units.
    machine::MachineDescription
    connectedControllerMachine(QMap<QString, double>* workOffsets = nullptr) const;
    // Opens connectedControllerMachine() on the same link (the single session closes first)
    // and connects it, with the work origins carried over. False with *error.
    bool openConnectedControllerAsMachine(QString* error);
    machine::Machine* machine() const { return m_machine.get(); }
    bool hasMachine() const { return m_machine != nullptr; }
    QString machinePath() const { return m_machinePath; }
    // The open machine's work offsets (loaded for its file when it opens, none when closed):
    // one set for the position display, Go to and programs (issue 28, item 3).
    MachineWorkOffsets* workOffsets() const { return m_workOffsets; }
    QString selectedController() const { return m_selectedId; }
    void selectController(const QString& controllerId);
    void connectMachine();
    void disconnectMachine();
    // Connected or connecting: some controller of the machine.
    bool machineLinkBusy() const;
    // The machine's one jog input ended (JogController jogs through Machine::jog itself).
    void endMachineJog();
    // The whole machine as one status for what speaks of all of it (the safety banner): the
    // worst link over the controllers; panic, setup incomplete, motion unconfirmed and busy of
    // any; each axis referenced only if it is on every controller that has it. Without a
    // machine: the session's link and status.
    MachineStatus machineWideStatus(LinkState* link) const;
    // How the positions are known, the worst over every axis (Unknown without an axis): with
    // a machine, each axis as Machine::axisStatus says (the source Go to, the check and the
    // referencing lamps judge by); else the controller's axes the same way (issue 28, item 4).
    machine::PositionKnowledge positionKnowledge() const;

Q_SIGNALS:
    void machineChanged(); // a machine was opened or closed
    // A controller of the machine failed; the others were told to stop (Machine).
    void machineControllerFailed(const QString& controllerId, const QString& message);
    void machineStatusChanged();
    // A controller's setup from the machine file was written on connect, or failed
    // (machine::MachineSetup; the message says which file and how many values, or why not).
    void machineSetupWritten(const QString& controllerId, bool ok, const QString& message);
    void modelChanged();
    void unitsChanged();
    // A UI-level event: the operator pressed panic (positions are lost from now on).
    void panicTriggered();
    void knownParametersChanged();
    void softLimitsChanged();

public Q_SLOTS:
    // Each controller's request (with a machine: Machine::stop/panic; else the one session's,
    // under an empty id), for callers that follow them to the acknowledgement.
    QMap<QString, RequestId> stop();
    QMap<QString, RequestId> panic();
    void reset(); // the controller's reset: its values are unknown afterwards

private:
    void loadUnits();
    void loadSoftLimits();
    QString settingsPrefix(Axis axis) const;
    void relayFrom(ControllerSession* selected);
    void announceLink(); // the selected session's link state and status to every listener

    ControllerSession* m_session;
    std::unique_ptr<machine::Machine> m_machine;
    ControllerSession* m_selected = nullptr; // the machine's selected controller
    QString m_selectedId;
    QString m_machinePath;
    MachineWorkOffsets* m_workOffsets;
    const ModelInfo* m_singleModel = nullptr; // the connection bar's model while a machine is open
    QList<QMetaObject::Connection> m_relay;
    const ModelInfo* m_model = nullptr;
    QString m_port;
    QMap<Axis, AxisUnits> m_units;
    ParameterSet m_known;
    SoftLimits m_softLimits;
    QMap<RequestId, ParameterSet> m_pendingWrites;
    QSet<RequestId> m_pendingReads;
    bool m_setupIncomplete = false;
};

} // namespace stepdeck::ui
