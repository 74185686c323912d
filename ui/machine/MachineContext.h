#pragma once
#include "controller/ControllerSession.h"
#include <QObject>

namespace stepdeck::ui {

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
class MachineContext : public QObject
{
    Q_OBJECT
public:
    explicit MachineContext(QObject* parent = nullptr);
    ~MachineContext() override;

    ControllerSession* session() const { return m_session; }
    const ModelInfo* model() const { return m_model; }
    Capabilities capabilities() const;
    QList<Axis> axes() const;
    ParameterSchema schema() const;
    QString modelId() const;
    QString portName() const { return m_port; }
    bool isConnected() const;
    const MachineStatus& status() const { return m_session->status(); }

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

    AxisUnits units(Axis axis) const;
    void setUnits(Axis axis, const AxisUnits& units);
    // Machine position in steps -> work position in user units (or steps when none set).
    double toUserUnits(Axis axis, qint64 machineSteps) const;
    QString unitName(Axis axis) const;
    // What the model's machine positions count, translated ("steps"; laser axes: "units"):
    // Capabilities::positionUnit, never a guess from the model id.
    QString machineUnitName() const;

Q_SIGNALS:
    void modelChanged();
    void unitsChanged();
    // A UI-level event: the operator pressed panic (positions are lost from now on).
    void panicTriggered();
    void knownParametersChanged();
    void softLimitsChanged();

public Q_SLOTS:
    void stop();
    void panic();
    void reset(); // the controller's reset: its values are unknown afterwards

private:
    void loadUnits();
    void loadSoftLimits();
    QString settingsPrefix(Axis axis) const;

    ControllerSession* m_session;
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
