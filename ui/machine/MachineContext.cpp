#include "MachineContext.h"
#include "ConnectionMachine.h"
#include "MachineMdi.h"
#include "drives/PositionErrorResetButton.h"
#include "machine/Machine.h"
#include "program/MachineTools.h"
#include "program/MachineWorkOffsets.h"
#include "protocols/Registry.h"
#include <QCoreApplication>

namespace stepdeck::ui {

QString modelDisplayName(const ModelInfo& model)
{
    // Registry names are English data; each model's folder lists its name for lupdate.
    return QCoreApplication::translate("Models", model.displayName.toUtf8().constData());
}

MachineContext::MachineContext(QObject* parent)
    : QObject(parent), m_session(new ControllerSession(this)),
      m_workOffsets(new program::MachineWorkOffsets(this)), m_tools(new program::MachineTools(this))
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
            const bool verified = m_pendingVerified.remove(r.id);
            if (r.ok()) {
                addKnownParameters(written, false);
                if (verified) // read back and compared by the adapter
                    merge(&m_readBack, readableOnly(written));
            }
        } else if (m_pendingReads.remove(r.id) && r.value.canConvert<ParameterSet>()) {
            if (r.ok())
                addKnownParameters(r.value.value<ParameterSet>(), true);
            else // some drives answered: what did come back was read back
                merge(&m_readBack, r.value.value<ParameterSet>());
        }
    });
    m_mdi = new MachineMdi(this, this);
}

RequestId MachineContext::writeParameters(const ParameterSet& values, bool verify)
{
    const RequestId id = session()->writeParameters(values, verify);
    m_pendingWrites.insert(id, values);
    if (verify)
        m_pendingVerified.insert(id);
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
    return m_selected ? m_selected->spec().port : QString();
}

void MachineContext::selectModel(const QString& modelId)
{
    const ModelInfo* model = findModel(modelId);
    if (m_machine && !m_connectionMachine) {
        m_singleModel = model; // its machine is shown when the file's is closed
        return;
    }
    if (model == m_model && (m_machine || !model))
        return;
    openIdleConnectionMachine(model);
}

bool MachineContext::connectTo(const ModelInfo& model, const ConnectionSpec& spec, QString* error)
{
    if (m_machine && !m_connectionMachine) {
        if (error)
            *error = tr("A machine is open: close it to connect a single controller.");
        return false;
    }
    // The session the panels listen to is re-created for this link: the machine that used it
    // goes first.
    uninstall();
    auto created = std::make_unique<machine::Machine>();
    created->lendSession(m_session);
    // The core's messages name this window's buttons, not CLI commands (issue 16).
    ControllerOptions base = spec.options;
    base.actionNames.insert(PositionErrorResetButton::operationName(),
                            PositionErrorResetButton::actionName());
    created->setBaseOptions(base);
    QString why;
    if (!created->create(connectionMachineOf(model, spec), &why)) {
        if (error)
            *error = why;
        openIdleConnectionMachine(&model);
        return false;
    }
    install(std::move(created), QString(), true);
    m_machine->open();
    return true;
}

void MachineContext::openIdleConnectionMachine(const ModelInfo* model)
{
    uninstall(); // its session may be the one the new machine runs on
    QString why;
    if (model) {
        // Not connected: the port is the connection bar's business until connectTo.
        ConnectionSpec spec;
        spec.port = QStringLiteral("none");
        auto created = std::make_unique<machine::Machine>();
        created->lendSession(m_session);
        if (created->create(connectionMachineOf(*model, spec), &why)) {
            install(std::move(created), QString(), true);
            return;
        }
        qWarning("StepDeck: no machine of model %s: %s", qPrintable(model->id), qPrintable(why));
    }
    // No machine at all: the panels show nothing to move.
    m_workOffsets->load(QString());
    m_tools->load(QString());
    m_model = nullptr;
    forgetKnownParameters();
    Q_EMIT modelChanged();
    Q_EMIT machineChanged();
    announceLink();
}

void MachineContext::disconnectFromController()
{
    disconnectMachine();
}

QMap<QString, RequestId> MachineContext::stop()
{
    if (!m_machine)
        return {};
    return m_machine->stop(); // every controller at once
}

QMap<QString, RequestId> MachineContext::panic()
{
    if (!m_machine)
        return {};
    const QMap<QString, RequestId> requests = m_machine->panic(); // every controller at once
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

void MachineContext::merge(ParameterSet* into, const ParameterSet& set)
{
    for (auto it = set.cbegin(); it != set.cend(); ++it) {
        ParameterValue& known = (*into)[it.key()];
        if (it.value().isPerAxis()) {
            for (auto a = it.value().perAxis.cbegin(); a != it.value().perAxis.cend(); ++a)
                known.perAxis.insert(a.key(), a.value());
        } else {
            known.global = it.value().global;
        }
    }
}

ParameterSet MachineContext::readableOnly(const ParameterSet& set) const
{
    const ParameterSchema s = schema();
    ParameterSet out;
    for (auto it = set.cbegin(); it != set.cend(); ++it) {
        const ParameterSpec* spec = s.find(it.key());
        if (spec && spec->readable)
            out.insert(it.key(), it.value());
    }
    return out;
}

void MachineContext::addKnownParameters(const ParameterSet& set, bool readBack)
{
    merge(&m_known, set);
    if (readBack) {
        merge(&m_readBack, set);
    } else { // the device holds what was written now, not what was read before
        for (auto it = set.cbegin(); it != set.cend(); ++it) {
            if (!m_readBack.contains(it.key()))
                continue;
            ParameterValue& old = m_readBack[it.key()];
            for (auto a = it.value().perAxis.cbegin(); a != it.value().perAxis.cend(); ++a)
                old.perAxis.remove(a.key());
            if (!it.value().isPerAxis())
                old.global = QVariant();
        }
    }
    Q_EMIT knownParametersChanged();
}

void MachineContext::forgetKnownParameters()
{
    m_known.clear();
    m_readBack.clear();
    m_pendingWrites.clear(); // answers to requests of an earlier link count for nothing
    m_pendingVerified.clear();
    m_pendingReads.clear();
    Q_EMIT knownParametersChanged();
}

QString MachineContext::machineUnitName() const
{
    return QCoreApplication::translate("Units", capabilities().positionUnit);
}

QString MachineContext::axisCountName(const machine::MachineAxis& axis) const
{
    // What the controller counts (Capabilities::positionUnit: laser axes count "units").
    const ControllerSession* s = m_machine ? m_machine->session(axis.controller) : nullptr;
    return s ? QCoreApplication::translate("Units", s->capabilities().positionUnit)
             : QCoreApplication::translate("stepdeck::ui::MachineDro", "steps");
}

QString MachineContext::axisUnitName(const machine::MachineAxis& axis) const
{
    switch (axis.unit) {
    case machine::AxisUnit::Millimetre:
        return QCoreApplication::translate("stepdeck::ui::MachineDro", "mm");
    case machine::AxisUnit::Degree:
        return QCoreApplication::translate("stepdeck::ui::MachineDro", "deg");
    case machine::AxisUnit::Step:
        break;
    }
    return axisCountName(axis);
}

} // namespace stepdeck::ui
