#include "MachineContext.h"
#include "drives/PositionErrorResetButton.h"
#include "machine/Machine.h"
#include "machine/MachineWorkOffsets.h"
#include "protocols/Registry.h"
#include <QCoreApplication>
#include <QSettings>

namespace stepdeck::ui {

QString modelDisplayName(const ModelInfo& model)
{
    // Registry names are English data; each model's folder lists its name for lupdate.
    return QCoreApplication::translate("Models", model.displayName.toUtf8().constData());
}

MachineContext::MachineContext(QObject* parent)
    : QObject(parent), m_session(new ControllerSession(this)),
      m_workOffsets(new MachineWorkOffsets(this))
{
    connect(m_session, &ControllerSession::linkStateChanged, this, [this](LinkState state) {
        if (state != LinkState::Connected)
            forgetKnownParameters(); // a new link may meet a reset or power-cycled device
    });
    connect(m_session, &ControllerSession::statusChanged, this, [this](const MachineStatus& s) {
        // A board that reports its setup incomplete again has lost it (power cycle).
        if (s.setupIncomplete && !m_setupIncomplete)
            forgetKnownParameters();
        m_setupIncomplete = s.setupIncomplete;
    });
    connect(m_session, &ControllerSession::requestFinished, this, [this](const CommandResult& r) {
        if (m_pendingWrites.contains(r.id)) {
            const ParameterSet written = m_pendingWrites.take(r.id);
            if (r.ok())
                addKnownParameters(written);
        } else if (m_pendingReads.remove(r.id) && r.ok() && r.value.canConvert<ParameterSet>()) {
            addKnownParameters(r.value.value<ParameterSet>());
        }
    });
}

RequestId MachineContext::writeParameters(const ParameterSet& values, bool verify)
{
    const RequestId id = session()->writeParameters(values, verify);
    m_pendingWrites.insert(id, values);
    return id;
}

RequestId MachineContext::readParameters(const QStringList& names)
{
    const RequestId id = session()->readParameters(names);
    m_pendingReads.insert(id);
    return id;
}

MachineContext::~MachineContext()
{
    // Quietly: the window's panels may be half destroyed by now.
    for (const QMetaObject::Connection& c : std::as_const(m_relay))
        disconnect(c);
    if (m_machine) {
        m_machine->disconnect(this);
        m_machine->destroy(); // every controller's stop, flushed, before its port closes
    }
    m_session->destroy();
}

Capabilities MachineContext::capabilities() const
{
    // The session's are the controller's own (they may depend on the axis map).
    if (session()->isCreated())
        return session()->capabilities();
    return m_model ? m_model->capabilities : Capabilities{};
}

QList<Axis> MachineContext::axes() const
{
    return capabilities().axes;
}

ParameterSchema MachineContext::schema() const
{
    return m_model ? m_model->schema : ParameterSchema{};
}

QString MachineContext::modelId() const
{
    return m_model ? m_model->id : QString();
}

bool MachineContext::isConnected() const
{
    return session()->isCreated() && session()->linkState() == LinkState::Connected;
}

QString MachineContext::portName() const
{
    return m_selected ? m_selected->spec().port : m_port;
}

void MachineContext::selectModel(const QString& modelId)
{
    const ModelInfo* model = findModel(modelId);
    if (m_machine) {
        m_singleModel = model; // shown again when the machine is closed
        return;
    }
    if (model == m_model)
        return;
    if (m_session->isCreated())
        m_session->destroy();
    m_model = model;
    loadUnits();
    loadSoftLimits();
    Q_EMIT modelChanged();
}

bool MachineContext::connectTo(const ModelInfo& model, const ConnectionSpec& given, QString* error)
{
    // The core's messages name this window's buttons, not CLI commands (issue 16).
    if (m_machine) {
        if (error)
            *error = tr("A machine is open: close it to connect a single controller.");
        return false;
    }
    ConnectionSpec spec = given;
    spec.options.actionNames.insert(PositionErrorResetButton::operationName(),
                                    PositionErrorResetButton::actionName());
    const ModelInfo* before = m_model;
    if (!m_session->create(model, spec, error))
        return false;
    m_model = m_session->model();
    m_port = spec.port;
    if (m_model != before) {
        loadUnits();
        loadSoftLimits();
        Q_EMIT modelChanged();
    }
    m_session->open();
    return true;
}

void MachineContext::disconnectFromController()
{
    if (m_machine)
        disconnectMachine();
    else if (m_session->isCreated())
        m_session->close();
}

QMap<QString, RequestId> MachineContext::stop()
{
    if (m_machine)
        return m_machine->stop(); // every controller at once
    return {{QString(), m_session->stop()}};
}

QMap<QString, RequestId> MachineContext::panic()
{
    const QMap<QString, RequestId> requests =
        m_machine ? m_machine->panic() : QMap<QString, RequestId>{{QString(), m_session->panic()}};
    // Only a panic the model can send loses positions; EMIS and laser axes refuse it (the
    // refusal says why), and their positions stay what they were.
    if (capabilities().panic)
        Q_EMIT panicTriggered();
    return requests;
}

void MachineContext::reset()
{
    session()->reset();
    forgetKnownParameters();
}

void MachineContext::addKnownParameters(const ParameterSet& set)
{
    for (auto it = set.cbegin(); it != set.cend(); ++it) {
        ParameterValue& known = m_known[it.key()];
        if (it.value().isPerAxis()) {
            for (auto a = it.value().perAxis.cbegin(); a != it.value().perAxis.cend(); ++a)
                known.perAxis.insert(a.key(), a.value());
        } else {
            known.global = it.value().global;
        }
    }
    Q_EMIT knownParametersChanged();
}

void MachineContext::forgetKnownParameters()
{
    m_known.clear();
    m_pendingWrites.clear(); // answers to requests of an earlier link count for nothing
    m_pendingReads.clear();
    Q_EMIT knownParametersChanged();
}

int MachineContext::referenceDirection(Axis axis) const
{
    const QString key = QStringLiteral("reference/%1/%2/direction").arg(modelId(), axisName(axis));
    return QSettings().value(key, -1).toInt();
}

int MachineContext::referenceOrder(Axis axis) const
{
    const QString key = QStringLiteral("reference/%1/%2/order").arg(modelId(), axisName(axis));
    return QSettings().value(key, axis == Axis::Z ? 1 : 2).toInt();
}

void MachineContext::setReference(Axis axis, int direction, int order)
{
    const QString key = QStringLiteral("reference/%1/%2/").arg(modelId(), axisName(axis));
    QSettings settings;
    settings.setValue(key + QStringLiteral("direction"), direction);
    settings.setValue(key + QStringLiteral("order"), order);
}

QString MachineContext::settingsPrefix(Axis axis) const
{
    return QStringLiteral("units/%1/%2/").arg(modelId(), axisName(axis));
}

void MachineContext::loadUnits()
{
    m_units.clear();
    QSettings settings;
    for (Axis axis : axes()) {
        AxisUnits u;
        const QString p = settingsPrefix(axis);
        u.stepsPerUnit = settings.value(p + QStringLiteral("stepsPerUnit"), 0.0).toDouble();
        u.unit = settings.value(p + QStringLiteral("unit"), QStringLiteral("mm")).toString();
        u.workOffset = settings.value(p + QStringLiteral("workOffset"), 0).toLongLong();
        m_units.insert(axis, u);
    }
}

void MachineContext::loadSoftLimits()
{
    m_softLimits = SoftLimits{};
    const QSettings settings;
    for (Axis axis : axes()) {
        const QString p = QStringLiteral("softLimits/%1/%2/").arg(modelId(), axisName(axis));
        AxisSoftLimit l;
        l.enabled = settings.value(p + QStringLiteral("enabled"), true).toBool();
        l.rangeSet = settings.value(p + QStringLiteral("rangeSet"), false).toBool();
        l.minimum = settings.value(p + QStringLiteral("minimum"), 0).toLongLong();
        l.maximum = settings.value(p + QStringLiteral("maximum"), 0).toLongLong();
        l.rangeSet = l.rangeSet && l.maximum > l.minimum;
        m_softLimits.set(axis, l);
    }
    m_session->setSoftLimits(m_softLimits);
    Q_EMIT softLimitsChanged();
}

void MachineContext::setSoftLimit(Axis axis, const AxisSoftLimit& limit)
{
    if (m_machine)
        return; // a machine's limits are its file's (in units), enforced by its sessions
    AxisSoftLimit l = limit;
    l.rangeSet = l.rangeSet && l.maximum > l.minimum;
    m_softLimits.set(axis, l);
    QSettings settings;
    const QString p = QStringLiteral("softLimits/%1/%2/").arg(modelId(), axisName(axis));
    settings.setValue(p + QStringLiteral("enabled"), l.enabled);
    settings.setValue(p + QStringLiteral("rangeSet"), l.rangeSet);
    settings.setValue(p + QStringLiteral("minimum"), l.minimum);
    settings.setValue(p + QStringLiteral("maximum"), l.maximum);
    m_session->setSoftLimits(m_softLimits);
    Q_EMIT softLimitsChanged();
}

qint64 MachineContext::toMachineSteps(Axis axis, double userValue) const
{
    const AxisUnits u = units(axis);
    const double steps = u.stepsPerUnit > 0 ? userValue * u.stepsPerUnit : userValue;
    if (!qIsFinite(steps))
        return u.workOffset;
    // double -> qint64 outside the range is undefined: bound it first (far beyond any axis).
    return qRound64(qBound(-1e15, steps, 1e15)) + u.workOffset;
}

AxisUnits MachineContext::units(Axis axis) const
{
    return m_units.value(axis);
}

void MachineContext::setUnits(Axis axis, const AxisUnits& units)
{
    m_units.insert(axis, units);
    QSettings settings;
    const QString p = settingsPrefix(axis);
    settings.setValue(p + QStringLiteral("stepsPerUnit"), units.stepsPerUnit);
    settings.setValue(p + QStringLiteral("unit"), units.unit);
    settings.setValue(p + QStringLiteral("workOffset"), units.workOffset);
    Q_EMIT unitsChanged();
}

double MachineContext::toUserUnits(Axis axis, qint64 machineSteps) const
{
    const AxisUnits u = units(axis);
    const qint64 work = machineSteps - u.workOffset;
    return u.stepsPerUnit > 0 ? double(work) / u.stepsPerUnit : double(work);
}

QString MachineContext::unitName(Axis axis) const
{
    const AxisUnits u = units(axis);
    return u.stepsPerUnit > 0 ? u.unit : machineUnitName();
}

QString MachineContext::machineUnitName() const
{
    return QCoreApplication::translate("Units", capabilities().positionUnit);
}

} // namespace stepdeck::ui
