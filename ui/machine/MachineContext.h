#pragma once
#include "controller/ControllerSession.h"
#include <QObject>
#include <memory>

namespace stepdeck::machine {
class Machine;
struct MachineDescription;
struct MachineAxis;
enum class PositionKnowledge;
} // namespace stepdeck::machine

namespace stepdeck::program {
class MachineTools;
class MachineWorkOffsets;
} // namespace stepdeck::program

namespace stepdeck::ui {

class MachineMdi;

// A model's display name in the current language (context "Models").
QString modelDisplayName(const ModelInfo& model);

// The one object every panel shares: the machine (the only path to the controllers), its
// selected controller and that controller's model. Panels rebuild on modelChanged().
//
// Every connection is a machine (issue 28, item 0): a machine file opens as itself
// (openMachine()); the connection bar's model and port open as a machine of that one
// controller (connectTo(); before it connects, selectModel() shows the model's machine
// unconnected). So every panel reads one model of axes, units, offsets and referenced state:
// the machine's. session() is the selected controller's session, so every per-controller
// page works on it. Panels connect to session() once, when they are built: that object (the
// context's own session, lent to the connection's machine: Machine::lendSession) stays their
// signal source; with a machine file open it relays the selected controller's signals
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
    // The selected controller's name for one of its axes ("feeder" where the operator named
    // it, issue 32; else X, Y, ...). Model operations keep taking the default names.
    QString controllerAxisName(Axis axis) const
    {
        return session()->spec().options.axisNames.name(axis);
    }

    // Chooses the connection bar's model: without a machine file open, its machine of one
    // controller (connectionMachineOf), unconnected, is what the panels show.
    void selectModel(const QString& modelId);
    // Opens model (a registry entry) on spec as a machine of that one controller
    // (connectionMachineOf; spec's options are every session's base options) and connects it;
    // false and a reason on failure (refused while a machine file is open).
    bool connectTo(const ModelInfo& model, const ConnectionSpec& spec, QString* error);
    // The connection machine's link closes (the machine stays, unconnected); a machine file's
    // controllers all close.
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
    // Merged per axis; readBack: the device reported these values (a read), else they were
    // written and not read back since.
    void addKnownParameters(const ParameterSet& set, bool readBack = false);
    void forgetKnownParameters();
    // The values the device itself last reported in this link session: a read (also one that
    // failed for some drives), or a Write & verify that succeeded. A value written since
    // without reading it back is in knownParameters() only. Forgotten with knownParameters().
    const ParameterSet& readBackParameters() const { return m_readBack; }

    // What the model's machine positions count, translated ("steps"; laser axes: "units"):
    // Capabilities::positionUnit, never a guess from the model id.
    QString machineUnitName() const;
    // An axis' unit as the read-out shows it, translated: mm, deg, or what its controller
    // counts (axisCountName: "steps", laser axes "units").
    QString axisUnitName(const machine::MachineAxis& axis) const;
    QString axisCountName(const machine::MachineAxis& axis) const;

    // A machine file (issue 19). openMachine reads and validates the file (MachineFile) and,
    // only if all of it is valid, closes the machine open now and creates the new one's
    // sessions (links not opened: connectMachine()). False with *error naming the field.
    bool openMachine(const QString& path, QString* error);
    bool openMachine(const machine::MachineDescription& description, QString* error,
                     const QString& path = QString());
    // Every controller stops and closes; back to the connection bar's model, unconnected.
    void closeMachine();
    machine::Machine* machine() const { return m_machine.get(); }
    bool hasMachine() const { return m_machine != nullptr; }
    // The machine of the connection bar's one controller (connectTo, selectModel), not of a
    // file: the connection bar connects and disconnects it.
    bool isConnectionMachine() const { return m_machine && m_connectionMachine; }
    // A machine opened from a file (or the editor): its own bar connects it, not the
    // connection bar.
    bool hasMachineFile() const { return m_machine && !m_connectionMachine; }
    QString machinePath() const { return m_machinePath; }
    // The open machine's work offsets (loaded for its file when it opens, none when closed):
    // one set for the position display, Go to and programs (issue 28, item 3).
    program::MachineWorkOffsets* workOffsets() const { return m_workOffsets; }
    program::MachineTools* tools() const { return m_tools; } // the machine's tool table (issue 29)
    // One G-code line at a time on the machine: the MDI line and Go to (issue 31).
    MachineMdi* mdi() const { return m_mdi; }
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
    // any; each axis referenced only if it is on every controller that has it.
    MachineStatus machineWideStatus(LinkState* link) const;
    // How the positions are known, the worst over every axis (Unknown without an axis), each
    // as Machine::axisStatus says: the source Go to, the check and the referencing lamps
    // judge by (issue 28, item 4).
    machine::PositionKnowledge positionKnowledge() const;

Q_SIGNALS:
    void machineChanged(); // a machine was opened or closed
    // A controller of the machine failed; the others were told to stop (Machine).
    void machineControllerFailed(const QString& controllerId, const QString& message);
    // After a stop, a panic or M2/M30: spindle and coolant off, or why not (Machine).
    void machineSpindleAndCoolantOff(bool ok, const QString& message);
    void machineStatusChanged();
    // The machine refused or ended a jog of a controller (Machine::jogRefused: a jog by
    // targets whose axis position is unknown, a target the controller refused).
    void machineJogRefused(const QString& controllerId, const QString& message);
    // A controller's setup from the machine file was written on connect, or failed
    // (machine::MachineSetup; the message says which file and how many values, or why not).
    void machineSetupWritten(const QString& controllerId, bool ok, const QString& message);
    void modelChanged();
    // A UI-level event: the operator pressed panic (positions are lost from now on).
    void panicTriggered();
    void knownParametersChanged();

public Q_SLOTS:
    // Each controller's request (Machine::stop/panic; none without a machine), for callers
    // that follow them to the acknowledgement.
    QMap<QString, RequestId> stop();
    QMap<QString, RequestId> panic();
    void reset(); // the controller's reset: its values are unknown afterwards

private:
    // The machine open now stops and closes, quietly (the caller announces what follows).
    void uninstall();
    // Replaces the machine (the one open now stops and closes first) by created.
    void install(std::unique_ptr<machine::Machine> created, const QString& path,
                 bool connectionMachine);
    // The connection bar's model as a machine of one controller, unconnected (none: no model).
    void openIdleConnectionMachine(const ModelInfo* model);
    void relayFrom(ControllerSession* selected);
    void announceLink(); // the selected session's link state and status to every listener
    static void merge(ParameterSet* into, const ParameterSet& set); // per axis
    ParameterSet readableOnly(const ParameterSet& set) const;       // what the schema reads back

    // The panels' signal source: the connection machine's own session (lent to its Machine),
    // and with a machine file open the relay of its selected controller's session.
    ControllerSession* m_session;
    std::unique_ptr<machine::Machine> m_machine;
    bool m_connectionMachine = false;
    ControllerSession* m_selected = nullptr; // the machine's selected controller
    QString m_selectedId;
    QString m_machinePath;
    program::MachineWorkOffsets* m_workOffsets;
    program::MachineTools* m_tools;
    MachineMdi* m_mdi = nullptr;              // made last: it follows machineChanged()
    const ModelInfo* m_singleModel = nullptr; // the connection bar's model while a file is open
    QList<QMetaObject::Connection> m_relay;
    const ModelInfo* m_model = nullptr;
    ParameterSet m_known;
    ParameterSet m_readBack;
    QMap<RequestId, ParameterSet> m_pendingWrites;
    QSet<RequestId> m_pendingVerified; // writes that read their values back
    QSet<RequestId> m_pendingReads;
    bool m_setupIncomplete = false;
};

} // namespace stepdeck::ui
