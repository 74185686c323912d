// Link, drive initialisation, status sweeps and the normalised status of a Nanotec bus.
#include "NanotecController.h"
#include "Logging.h"
#include "NanotecClosedLoop.h"
#include "NanotecLogging.h"
#include "NanotecModel.h"
#include "transport/Transport.h"
#include <QtMath>

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
        Drive d;
        d.axis = it.key();
        d.address = it.value();
        m_drives.insert(it.key(), d);
        mutableStatus().axes.insert(it.key(), AxisStatus{});
    }
    m_bus = new NanotecBus(transport, this);
    m_closedLoop = new NanotecClosedLoop(this);
    m_bus->setDefaultTimeout(options.commandTimeoutMs);
    connect(m_bus, &NanotecBus::unsolicited, this, &NanotecController::onUnsolicited);
    connect(m_bus, &NanotecBus::garbage, this, [this] { ++mutableStatus().resyncCount; });
    connect(m_bus, &NanotecBus::traffic, this,
            [this](TrafficRecord::Direction dir, const QByteArray& bytes, bool poll) {
                recordTraffic(dir, bytes, poll);
            });
    m_userPollMs = options.pollIntervalMs;
    m_poller.setMissLimit(options.missedPollsForLinkLoss);
    connect(&m_poller, &StatusPoller::pollDue, this, &NanotecController::onPollDue);
    connect(&m_poller, &StatusPoller::linkLost, this, [this](int misses) {
        loseLink(tr("no drive answered %1 status sweeps in a row").arg(misses));
    });
    connect(&m_poller, &StatusPoller::rateChanged, this, &Controller::pollRateChanged);
    if (transport) {
        connect(transport, &Transport::opened, this, &NanotecController::onTransportOpened);
        connect(transport, &Transport::failed, this,
                [this](const QString& reason) { handleTransportFailure(reason); });
    }
    updateStatus();
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
    return tr("drive %1 (axis %2)").arg(m_drives.value(axis).address).arg(axisName(axis));
}

int NanotecController::sweepBudgetMs() const
{
    // Per drive and sweep: "#1$\r" + "001$17\r" + "#1C\r" + "001C-1234567\r" = 27 characters,
    // plus a quarter of "#1ZY\r" + "001ZY196671\r" for the inputs: about 31 characters.
    int drives = 0;
    for (const Drive& d : m_drives)
        drives += d.responding ? 1 : 0;
    const double us = qMax(1, drives) * 31 * lineSettings().characterTimeUs();
    return int(qCeil(us / 1000.0));
}

int NanotecController::pollTimeoutMs() const
{
    // A status reply is under 15 characters (8 ms at 19200 baud): a short timeout keeps a
    // silent drive from stalling the sweep of the others.
    return qMin(options().commandTimeoutMs, 150);
}

void NanotecController::setPollInterval(int ms)
{
    m_userPollMs = qMax(1, ms);
    m_poller.setInterval(qMax(m_userPollMs, sweepBudgetMs()));
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
    if (m_pendingOpen)
        initialiseDrives();
    else if (m_pendingScan)
        runPendingScan();
}

void NanotecController::initialiseDrives()
{
    m_initialising = true;
    QList<Step> perDrive;
    for (Axis axis : m_drives.keys()) {
        // Firmware first (5.22): a drive that does not answer it is flagged and skipped; the
        // rest only fills caches, so a drive that answers but refuses one of them stays.
        Step identify = exchange(
            axis, "v",
            [this, axis](const Reply& r) {
                m_drives[axis].firmware = r.firmware.text;
                return Failure{};
            },
            NanotecBus::Priority::Command, 1);
        QList<Step> rest{
            // Auto status off (5.31): on a polled half-duplex bus a 'j' the drive sends by
            // itself collides with the poll of another drive.
            tolerant(exchange(axis, "J0")),
            tolerant(exchange(
                axis, "Ze", sink([this, axis](qint64 v) { m_drives[axis].limitSwitchType = v; }))),
            tolerant(exchange(axis, "Zu",
                              sink([this, axis](qint64 v) { m_drives[axis].minFrequency = v; }))),
            tolerant(exchange(axis, "Zo",
                              sink([this, axis](qint64 v) { m_drives[axis].maxFrequency = v; }))),
            tolerant(
                exchange(axis, "Zb", sink([this, axis](qint64 v) { m_drives[axis].ramp = v; }))),
            tolerant(exchange(
                axis, "$", sink([this, axis](qint64 v) { applyStatusWord(m_drives[axis], v); }))),
            tolerant(
                exchange(axis, "C", sink([this, axis](qint64 v) { m_drives[axis].position = v; }))),
        };
        perDrive << [this, axis, identify, rest](const Done& done) {
            identify([this, axis, rest, done](const Failure& f) {
                Drive& d = m_drives[axis];
                d.responding = f.kind != ErrorKind::Timeout && f.kind != ErrorKind::Cancelled;
                d.misses = d.responding ? 0 : m_poller.missLimit();
                if (!f.ok())
                    qCWarning(lcNanotec) << "initialising" << driveName(axis) << ":" << f.message;
                if (!d.responding)
                    return done({});
                runSteps(rest, [done](const Failure&) { done({}); });
            });
        };
    }
    runSteps(perDrive, [this](const Failure&) {
        m_initialising = false;
        QStringList silent;
        for (const Drive& d : m_drives) {
            if (!d.responding)
                silent << QString::number(d.address);
        }
        const RequestId id = m_pendingOpen;
        m_pendingOpen = 0;
        if (silent.size() == m_drives.size()) {
            const QString why = tr("no drive answered at address %1 (19200 baud 8N1)")
                                    .arg(silent.join(QStringLiteral(", ")));
            if (transport())
                transport()->close();
            setLinkState(LinkState::Disconnected, why);
            finishError(id, ErrorKind::Timeout, why);
            return;
        }
        setLinkState(LinkState::Connected);
        setPollInterval(m_userPollMs);
        m_poller.start();
        updateStatus();
        publishStatus();
        if (!silent.isEmpty())
            Q_EMIT errorOccurred(tr("no answer from drive %1; the other drives work")
                                     .arg(silent.join(QStringLiteral(", "))));
        finishOk(id);
    });
}

} // namespace stepdeck::nanotec
