// SoakFigures as JSON (the child process hands its figures to the parent this way, and
// --json prints them) and as text.
#include "Soak.h"

namespace stepdeck::bench {

namespace {
QJsonObject mapJson(const QMap<QString, qint64>& map)
{
    QJsonObject out;
    for (auto it = map.cbegin(); it != map.cend(); ++it)
        out.insert(it.key(), it.value());
    return out;
}

QMap<QString, qint64> mapFrom(const QJsonObject& json)
{
    QMap<QString, qint64> out;
    for (auto it = json.constBegin(); it != json.constEnd(); ++it)
        out.insert(it.key(), it.value().toInteger());
    return out;
}

QString mapText(const QMap<QString, qint64>& map)
{
    QStringList parts;
    for (auto it = map.cbegin(); it != map.cend(); ++it)
        parts << QStringLiteral("%1 %2").arg(it.key()).arg(it.value());
    return parts.isEmpty() ? QStringLiteral("none") : parts.join(QStringLiteral(", "));
}

// Every counter by its JSON name, so toJson and fromJson cannot drift apart.
template <typename F> void eachCounter(F f, SoakFigures& s)
{
    f("crashes", s.crashes);
    f("hangs", s.hangs);
    f("axesLeftMoving", s.axesLeftMoving);
    f("lostMoves", s.lostMoves);
    f("duplicatedMoves", s.duplicatedMoves);
    f("sessions", s.sessions);
    f("vanishes", s.vanishes);
    f("linkLosses", s.linkLosses);
    f("connectFailures", s.connectFailures);
    f("movingAtReconnect", s.movingAtReconnect);
    f("hostMovesOk", s.hostMovesOk);
    f("deviceMoves", s.deviceMoves);
    f("unconfirmedMoves", s.unconfirmedMoves);
    f("unmatchedDeviceMoves", s.unmatchedDeviceMoves);
    f("recoveries", s.recoveries);
    f("jogMoves", s.jogMoves);
    f("emergencyStops", s.emergencyStops);
    f("axesMoved", s.axesMoved);
}
} // namespace

QJsonObject SoakFigures::toJson() const
{
    QJsonObject out{
        {"model", model},     {"commands", commands},      {"seed", qint64(seed)},
        {"seconds", seconds}, {"faults", mapJson(faults)}, {"results", mapJson(results)},
        {"clean", clean()}};
    SoakFigures copy = *this;
    eachCounter([&](const char* name, qint64& v) { out.insert(QLatin1String(name), v); }, copy);
    return out;
}

SoakFigures SoakFigures::fromJson(const QJsonObject& json)
{
    SoakFigures s;
    s.model = json.value("model").toString();
    s.commands = json.value("commands").toInt();
    s.seed = quint32(json.value("seed").toInteger());
    s.seconds = json.value("seconds").toDouble();
    s.faults = mapFrom(json.value("faults").toObject());
    s.results = mapFrom(json.value("results").toObject());
    eachCounter(
        [&](const char* name, qint64& v) { v = json.value(QLatin1String(name)).toInteger(); }, s);
    return s;
}

QString SoakFigures::toText() const
{
    return QStringLiteral(
               "%1: %2 commands, seed %3, %4 s, %5 sessions\n"
               "  crashes %6  hangs %7  axes left moving %8  lost moves %9  duplicated moves %10\n"
               "  faults injected: %11\n"
               "  peer vanished %12 times; link lost without a vanish %13; failed connects %14; "
               "axes found moving after a vanish %15\n"
               "  moves (per axis): host told success %16, device started %17, started although "
               "the host was told it failed %18, device moves matching no command %19; operator "
               "recoveries after refusals %20; device moves made by jogs (not matched) %21; "
               "axes that moved at the device %24\n"
               "  emergency stops at the device (models without a stop command, axes still "
               "moving after a lost link) %22\n"
               "  results: %23")
        .arg(model)
        .arg(commands)
        .arg(seed)
        .arg(seconds, 0, 'f', 1)
        .arg(sessions)
        .arg(crashes)
        .arg(hangs)
        .arg(axesLeftMoving)
        .arg(lostMoves)
        .arg(duplicatedMoves)
        .arg(mapText(faults))
        .arg(vanishes)
        .arg(linkLosses)
        .arg(connectFailures)
        .arg(movingAtReconnect)
        .arg(hostMovesOk)
        .arg(deviceMoves)
        .arg(unconfirmedMoves)
        .arg(unmatchedDeviceMoves)
        .arg(recoveries)
        .arg(jogMoves)
        .arg(emergencyStops)
        .arg(mapText(results))
        .arg(axesMoved);
}

} // namespace stepdeck::bench
