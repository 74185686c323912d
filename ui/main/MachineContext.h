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
    // Creates the session for spec and opens the link; false and a reason on failure.
    bool connectTo(const ConnectionSpec& spec, QString* error);
    void disconnectFromController();

    AxisUnits units(Axis axis) const;
    void setUnits(Axis axis, const AxisUnits& units);
    // Machine position in steps -> work position in user units (or steps when none set).
    double toUserUnits(Axis axis, qint64 machineSteps) const;
    QString unitName(Axis axis) const;

Q_SIGNALS:
    void modelChanged();
    void unitsChanged();
    // A UI-level event: the operator pressed panic (positions are lost from now on).
    void panicTriggered();

public Q_SLOTS:
    void stop();
    void panic();

private:
    void loadUnits();
    QString settingsPrefix(Axis axis) const;

    ControllerSession* m_session;
    const ModelInfo* m_model = nullptr;
    QString m_port;
    QMap<Axis, AxisUnits> m_units;
};

} // namespace stepdeck::ui
