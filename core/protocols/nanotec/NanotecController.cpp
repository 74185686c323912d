// The Nanotec adapter: the link, the drive table and the Controller interface, each request
// handed to the part that does it (NanotecController.h).
#include "NanotecController.h"
#include "Logging.h"
#include "NanotecClosedLoop.h"
#include "NanotecLogging.h"
#include "NanotecModel.h"
#include "model/ModelOperations.h"
#include "transport/Transport.h"

namespace stepdeck::nanotec {

NanotecController::NanotecController(Transport* transport, const ControllerOptions& options,
                                     QObject* parent)
    : Controller(transport, options, parent)
{
    const QMap<Axis, int> map =
        options.axisAddresses.isEmpty() ? defaultAxisAddresses() : options.axisAddresses;
    QList<int> seen;
    for (auto it = map.cbegin(); it != map.cend(); ++it) {
        if (!isValidAddress(it.value()) || seen.contains(it.value())) {
            m_configError = tr("axis map: address %1 of axis %2 is invalid or used twice "
                               "(allowed 1..254, one drive per axis)")
                                .arg(it.value())
                                .arg(axisName(it.key()));
        }
        seen << it.value();
        HostDrive d;
        d.axis = it.key();
        d.address = it.value();
        m_drives.insert(it.key(), d);
        mutableStatus().axes.insert(it.key(), AxisStatus{});
    }
    m_bus = new NanotecBus(transport, this);
    m_closedLoop = new NanotecClosedLoop(this);
    m_bus->setDefaultTimeout(options.commandTimeoutMs);
    connect(m_bus, &NanotecBus::unsolicited, this,
            [this](const Reply& reply) { m_sweep.onUnsolicited(reply); });
    connect(m_bus, &NanotecBus::garbage, this, [this] { ++mutableStatus().resyncCount; });
    m_clock.start();
    connect(m_bus, &NanotecBus::exchanged, this,
            [this](int address, const QByteArray& body, bool answered) {
                m_held.onExchange(address, body, answered, nowMs());
            });
    connect(m_bus, &NanotecBus::traffic, this,
            [this](TrafficRecord::Direction dir, const QByteArray& bytes, bool poll) {
                recordTraffic(dir, bytes, poll);
            });
    m_userPollMs = options.pollIntervalMs;
    m_poller.setMissLimit(options.missedPollsForLinkLoss);
    connect(&m_poller, &StatusPoller::pollDue, this, [this] { m_sweep.onPollDue(); });
    connect(&m_poller, &StatusPoller::linkLost, this, [this](int misses) {
        loseLink(tr("no drive answered %1 status sweeps in a row").arg(misses));
    });
    connect(&m_poller, &StatusPoller::rateChanged, this, &Controller::pollRateChanged);
    if (transport) {
        connect(transport, &Transport::opened, this, &NanotecController::onTransportOpened);
        connect(transport, &Transport::failed, this,
                [this](const QString& reason) { handleTransportFailure(reason); });
    }
    m_sweep.updateStatus();
}

NanotecController::~NanotecController() = default;

Capabilities NanotecController::capabilities() const
{
    return nanotec::capabilities(m_drives.keys());
}

ParameterSchema NanotecController::schema() const
{
    return parameterSchema();
}

QString NanotecController::driveName(Axis axis) const
{
    return tr("drive %1 (axis %2)").arg(m_drives.value(axis).address).arg(nameOf(axis));
}

QString NanotecController::nameOf(Axis axis) const
{
    return options().axisNames.name(axis);
}

void NanotecController::setPollInterval(int ms)
{
    // As given, also below the time a sweep takes: the poller starts a sweep only when none is
    // in flight and times the interval from start to start, so a short interval means sweeps
    // back to back, never overlapping ones; commands still go between a sweep's exchanges
    // (NanotecStatus defers polls behind queued commands). Clamping to the sweep budget
    // (31 characters per drive, rounded up) left the bus idle up to a third of the time when
    // polls were asked for back to back (issue 21).
    m_userPollMs = qMax(1, ms);
    m_poller.setInterval(m_userPollMs);
}

void NanotecController::finishWith(RequestId id, const Failure& failure, const QVariant& value)
{
    if (failure.ok())
        finishOk(id, value);
    else
        finishError(id, failure.kind, failure.message);
}

HostDrive* NanotecController::driveFor(const QVariantMap& args, RequestId id)
{
    // The operator's name ("feeder", issue 32) or the default name the window sends.
    const auto axis =
        options().axisNames.find(args.value(operation::arg::kAxis, QStringLiteral("X")).toString());
    if (!axis || !m_drives.contains(*axis)) {
        finishError(id, ErrorKind::InvalidValue,
                    tr("unknown axis '%1' (this machine has %2)")
                        .arg(args.value(operation::arg::kAxis).toString())
                        .arg([this] {
                            QStringList n;
                            for (Axis a : m_drives.keys())
                                n << options().axisNames.name(a);
                            return n.join(QLatin1Char(','));
                        }()));
        return nullptr;
    }
    if (linkState() != LinkState::Connected) {
        finishError(id, ErrorKind::LinkDown, tr("not connected"));
        return nullptr;
    }
    return &m_drives[*axis];
}

// ---------------------------------------------------------------- link

void NanotecController::openLink(RequestId id)
{
    if (!m_configError.isEmpty())
        return finishError(id, ErrorKind::InvalidValue, m_configError);
    if (linkState() == LinkState::Connected)
        return finishOk(id);
    if (!transport())
        return finishError(id, ErrorKind::LinkDown, tr("no transport"));
    if (m_pendingOpen)
        return finishError(id, ErrorKind::Refused, tr("already connecting"));
    m_pendingOpen = id;
    setLinkState(LinkState::Connecting);
    if (transport()->isOpen())
        onTransportOpened();
    else
        transport()->open(lineSettings());
}

void NanotecController::onTransportOpened()
{
    m_bus->resetDecoder();
    m_held.forgetAll(); // a new link: the drives may have been anything meanwhile
    if (m_pendingOpen)
        m_sweep.initialiseDrives();
    else if (m_pendingScan)
        m_operations.runPendingScan();
}

// ---------------------------------------------------------------- the parts

void NanotecController::readParameters(RequestId id, const QStringList& names)
{
    m_parameters.readParameters(id, names);
}

void NanotecController::writeParameters(RequestId id, const ParameterSet& values, bool verify)
{
    m_parameters.writeParameters(id, values, verify);
}

void NanotecController::moveRelative(RequestId id, const AxisVector& steps)
{
    m_motion.moveRelative(id, steps);
}

void NanotecController::moveAbsolute(RequestId id, const AxisVector& targets)
{
    m_motion.moveAbsolute(id, targets);
}

void NanotecController::reference(RequestId id, const QMap<Axis, int>& directions)
{
    m_motion.referenceWithType(id, directions, false);
}

void NanotecController::velocityMove(RequestId id, const AxisVector& stepsPerS)
{
    m_motion.velocityMove(id, stepsPerS);
}

void NanotecController::stop(RequestId id)
{
    m_stop.stop(id);
}

void NanotecController::panic(RequestId id)
{
    m_stop.panic(id);
}

void NanotecController::reset(RequestId id)
{
    m_stop.reset(id);
}

void NanotecController::refreshStatus(RequestId id)
{
    m_sweep.refreshStatus(id);
}

void NanotecController::sendRaw(RequestId id, const QByteArray& bytes)
{
    m_operations.sendRaw(id, bytes);
}

void NanotecController::scanBus(RequestId id)
{
    m_operations.modelOperation(id, operation::kScan, {});
}

void NanotecController::modelOperation(RequestId id, const QString& name, const QVariantMap& args)
{
    m_operations.modelOperation(id, name, args);
}

void NanotecController::applyJogVelocity(const AxisVelocities& stepsPerS)
{
    m_jog.applyJogVelocity(stepsPerS);
}

QString NanotecController::jogRefusal() const
{
    return Controller::jogRefusal();
}

QString NanotecController::jogAxisRefusal(Axis axis, double target) const
{
    return m_motion.belowStartFrequency(axis, target);
}

double NanotecController::jogStopDistance(Axis axis, double speed) const
{
    return m_jog.jogStopDistance(axis, speed);
}

void NanotecController::sendSafetyStop(std::function<void(bool)> done)
{
    m_stop.sendSafetyStop(std::move(done));
}

void NanotecController::abortHostSide(ErrorKind kind, const QString& message)
{
    m_held.forgetAll();
    m_stop.abortHostSide(kind, message);
}

bool NanotecController::motionMayBeRunning() const
{
    return m_stop.motionMayBeRunning();
}

int NanotecController::safetyStopTimeoutMs() const
{
    return m_stop.safetyStopTimeoutMs();
}

} // namespace stepdeck::nanotec
