// laser-bridge: StepDeck is the motor axes of a laser marker, with the controller of --model
// and --port behind it (issue 9, section 2). The logic lives in core (bridge/LaserBridge);
// this file parses the command, connects both sides and runs until SIGINT/SIGTERM/SIGHUP.
#include "CliCommands.h"
#include "bridge/LaserBridge.h"
#include "transport/TransportFactory.h"
#include <QCoreApplication>
#include <QJsonObject>

namespace stepdeck::cli {

namespace {
using bridge::LaserBridge;
using bridge::LaserBridgeConfig;

constexpr int kShutdownWaitMs = 5000;

class LaserBridgeCommand
{
    Q_DECLARE_TR_FUNCTIONS(LaserBridgeCommand)
public:
    explicit LaserBridgeCommand(CliContext& c) : m_c(c) {}
    Outcome run(QStringList args);

private:
    Outcome parse(QStringList args);
    Outcome checkDoorInput();
    void print(const LaserBridge::LogEntry& entry) const;

    CliContext& m_c;
    QString m_laserPort;
    LaserBridgeConfig m_config;
};

Outcome LaserBridgeCommand::parse(QStringList args)
{
    const std::optional<QString> map = m_c.options.value("map");
    const std::optional<QString> scale = m_c.options.value("scale");
    const std::optional<QString> home = m_c.options.value("home");
    const std::optional<QString> door = m_c.options.value("door-input");
    if (args.size() != 1) {
        return Outcome::usage(tr("laser-bridge needs exactly one LASER_PORT (the serial port the "
                                 "laser's XYZ-control port is cabled to)"));
    }
    m_laserPort = args.first();
    int doorInput = 0;
    QString error;
    if ((map && !LaserBridgeConfig::parseMap(*map, &m_config.axisMap, &error)) ||
        (scale && !LaserBridgeConfig::parseScale(*scale, &m_config.scale, &error)) ||
        (home && !LaserBridgeConfig::parseHome(*home, &m_config.homeDirections, &error)) ||
        (door && !LaserBridgeConfig::parseDoorInput(*door, &doorInput, &error))) {
        return Outcome::usage(error);
    }
    if (door)
        m_config.doorInput = doorInput;
    if (const QString bad = m_config.validate(m_c.capabilities()); !bad.isEmpty())
        return Outcome::usage(tr("laser-bridge: %1").arg(bad));
    if (m_laserPort == m_c.options.port)
        return Outcome::usage(tr("laser-bridge: the laser's port and the controller's port are "
                                 "the same"));
    return Outcome::success();
}

Outcome LaserBridgeCommand::checkDoorInput()
{
    if (!m_config.doorInput)
        return Outcome::success();
    const MachineStatus& status = m_c.session.status();
    if (LaserBridge::doorInputState(status, *m_config.doorInput))
        return Outcome::success();
    return Outcome::failure(ExitUnsupported,
                            tr("%1 has no input the bridge can read as a door switch (--door-input "
                               "%2); the E-LAB start button is not one")
                                .arg(m_c.model->id)
                                .arg(*m_config.doorInput));
}

void LaserBridgeCommand::print(const LaserBridge::LogEntry& entry) const
{
    if (!m_c.json()) {
        printLine(LaserBridge::formatLogEntry(entry));
        return;
    }
    static const char* const kinds[] = {"fromLaser", "toLaser", "ignored", "note", "error"};
    printJson(QJsonObject{{"time", entry.time.toString(Qt::ISODateWithMs)},
                          {"kind", QString::fromLatin1(kinds[int(entry.kind)])},
                          {"frame", QString::fromLatin1(entry.frame.toHex())},
                          {"text", entry.text}});
}

Outcome LaserBridgeCommand::run(QStringList args)
{
    if (Outcome parsed = parse(args); !parsed.ok())
        return parsed;
    Outcome result = m_c.connect();
    if (result.ok())
        result = m_c.session.refresh();
    if (result.ok())
        result = checkDoorInput();
    if (!result.ok())
        return result;

    QObject holder;
    Transport* laserPort = createTransport(m_laserPort, &holder);
    LaserBridge bridge(&m_c.session.session(), laserPort, m_config);
    bool started = false;
    std::optional<QString> laserFailure;
    QObject::connect(&bridge, &LaserBridge::logged, &holder,
                     [this](const LaserBridge::LogEntry& e) { print(e); });
    QObject::connect(&bridge, &LaserBridge::started, &holder, [&] { started = true; });
    QObject::connect(&bridge, &LaserBridge::failed, &holder,
                     [&](const QString& why) { laserFailure = why; });
    bridge.start();
    const auto controllerLost = [this] {
        return m_c.session.session().linkState() != LinkState::Connected;
    };
    m_c.session.waitFor([&] { return started || laserFailure || controllerLost(); }, 10000);
    if (started) {
        // Serves until a signal, the laser port failing or the controller's link dropping.
        m_c.session.waitFor([&] { return laserFailure || controllerLost(); }, -1);
    }
    const bool signalled = m_c.session.takeInterrupt();
    bool finished = !bridge.isRunning();
    QObject::connect(&bridge, &LaserBridge::finished, &holder, [&] { finished = true; });
    bridge.shutdown();
    m_c.session.waitFor([&] { return finished; }, kShutdownWaitMs);
    if (laserFailure && !signalled)
        return Outcome::failure(ExitLinkDown,
                                tr("laser port %1: %2").arg(m_laserPort, *laserFailure));
    if (!started && !signalled)
        return Outcome::failure(ExitLinkDown, tr("laser port %1 did not open").arg(m_laserPort));
    if (controllerLost() && !signalled)
        return Outcome::failure(ExitLinkDown,
                                tr("%1: the controller's link was lost").arg(m_c.options.port));
    return Outcome::success();
}
} // namespace

Outcome cmdLaserBridge(CliContext& c, QStringList args)
{
    return LaserBridgeCommand(c).run(args);
}

} // namespace stepdeck::cli
