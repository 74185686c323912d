// stepdeck-bench --jog-latency: arguments, output and the default run's child (JogLatency.h).
#include "BenchOutput.h"
#include "JogLatency.h"
#include "controller/ControllerOptions.h"
#include "model/ModelInfo.h"
#include "model/NumberParsing.h"
#include "protocols/Registry.h"
#include <QApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QProcess>
#include <QSettings>
#include <QTemporaryDir>
#include <cmath>
#include <cstdio>

namespace stepdeck::bench {

namespace {

struct Options
{
    JogLatencyOptions jog;
    bool json = false;
};

// False with *error on a bad or unknown argument.
bool parse(const QStringList& args, Options* o, QString* error)
{
    for (int i = 0; i < args.size(); ++i) {
        const QString& a = args.at(i);
        qint64 n = 0;
        if (a == QLatin1String("--jog-latency")) {
            continue;
        } else if (a == QLatin1String("--jog-presses")) {
            const QString value = i + 1 < args.size() ? args.at(++i) : QString();
            if (numbers::parseInteger(value, 1, 10000, &n) != NumberError::None) {
                *error = QStringLiteral("--jog-presses needs a count from 1 to 10000");
                return false;
            }
            o->jog.presses = int(n);
        } else if (a == QLatin1String("--jog-paced")) {
            o->jog.paced = true;
        } else if (a == QLatin1String("--json")) {
            o->json = true;
        } else {
            *error = QStringLiteral("bad argument '%1'").arg(a);
            return false;
        }
    }
    return true;
}

QJsonValue ms(const std::optional<double>& value)
{
    return value ? QJsonValue(std::round(*value * 1000.0) / 1000.0) : QJsonValue();
}

QJsonObject latencyJson(const LatencyFigure& f)
{
    return {{"median", ms(f.medianMs)}, {"p99", ms(f.p99Ms)}, {"samples", f.samples}};
}

// {"jogLatencyMs": E-LAB's press figure, "jogLatency": {model: {pressMs, releaseMs, ...}},
//  "conditions": {"jog": {...}}, "notes": [...]}
QJsonObject toJson(const QList<JogLatencyFigure>& figures, const JogLatencyOptions& options)
{
    QJsonObject perModel;
    QJsonArray notes;
    QJsonObject headline;
    for (const JogLatencyFigure& f : figures) {
        perModel.insert(f.model, QJsonObject{{"pressMs", latencyJson(f.press)},
                                             {"releaseMs", latencyJson(f.release)},
                                             {"deviceRealtime", f.press.deviceRealtime}});
        if (!f.press.note.isEmpty())
            notes.append(QStringLiteral("jogLatency %1: %2").arg(f.model, f.press.note));
        if (f.model == QLatin1String("elab"))
            headline = latencyJson(f.press);
    }
    const QJsonObject conditions{
        {"presses", options.presses},
        {"holdMs", kJogHoldMs},
        {"pollIntervalMs", ControllerOptions{}.pollIntervalMs}, // the GUI's default
        {"wire", options.paced ? "paced at each model's line rate" : "unpaced"},
        {"platform", QGuiApplication::platformName()},
        {"input", "QTest press on the jog panel's X/Y pad at full +X deflection"}};
    return {{"jogLatencyMs", headline},
            {"jogLatency", perModel},
            {"conditions", QJsonObject{{"jog", conditions}}},
            {"notes", notes}};
}

QString figureText(const QJsonObject& f)
{
    if (f.value("median").isNull())
        return QStringLiteral("n/a");
    return QStringLiteral("median %1 ms, p99 %2 ms (%3 samples)")
        .arg(f.value("median").toDouble(), 0, 'f', 3)
        .arg(f.value("p99").toDouble(), 0, 'f', 3)
        .arg(f.value("samples").toInt());
}

} // namespace

QStringList jogLatencyText(const QJsonObject& figures)
{
    const QJsonObject c = figures.value("conditions").toObject().value("jog").toObject();
    QStringList lines{QStringLiteral("  jog latency (%1 platform, pty %2, %3 presses held %4 ms; "
                                     "at the device)")
                          .arg(c.value("platform").toString(), c.value("wire").toString())
                          .arg(c.value("presses").toInt())
                          .arg(c.value("holdMs").toInt())};
    const QJsonObject perModel = figures.value("jogLatency").toObject();
    for (auto it = perModel.constBegin(); it != perModel.constEnd(); ++it) {
        const QJsonObject m = it.value().toObject();
        lines << QStringLiteral("    %1 press -> first jog frame   %2")
                     .arg(it.key(), -8)
                     .arg(figureText(m.value("pressMs").toObject()))
              << QStringLiteral("    %1 release -> end of the jog  %2")
                     .arg(QString(), -8)
                     .arg(figureText(m.value("releaseMs").toObject()));
    }
    for (const QJsonValue& note : figures.value("notes").toArray())
        lines << QStringLiteral("    note: %1").arg(note.toString());
    return lines;
}

int jogLatencyMain(int argc, char** argv)
{
    bool asked = false;
    for (int i = 1; i < argc; ++i) {
        if (qstrcmp(argv[i], "--help") == 0 || qstrcmp(argv[i], "-h") == 0)
            return -1; // main() prints the usage
        asked = asked || qstrcmp(argv[i], "--jog-latency") == 0;
    }
    if (!asked)
        return -1;
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen"); // no window on anybody's desktop
    if (qEnvironmentVariableIsEmpty("QT_LOGGING_RULES"))
        qInstallMessageHandler(quiet); // before the platform's warnings
    QApplication application(argc, argv);
    Options options;
    QString error;
    if (!parse(application.arguments().mid(1), &options, &error)) {
        print(stderr, QStringLiteral("stepdeck-bench: %1").arg(error));
        return 2;
    }
    // The panel reads and writes the operator's jog settings: a settings file of its own.
    QTemporaryDir settings;
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settings.path());
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settings.path());
    QList<JogLatencyFigure> figures;
    for (const QString& id : kJogModels) {
        if (!options.json)
            print(stderr, QStringLiteral("measuring jog latency, %1 ...").arg(id));
        if (const ModelInfo* model = findModel(id)) {
            figures << measureJogLatency(*model, options.jog);
        } else {
            JogLatencyFigure missing;
            missing.model = id;
            missing.press.note = QStringLiteral("not built in");
            figures << missing;
        }
    }
    const QJsonObject out = toJson(figures, options.jog);
    if (options.json)
        print(stdout, QString::fromUtf8(QJsonDocument(out).toJson(QJsonDocument::Compact)));
    else
        print(stdout, jogLatencyText(out).join(QLatin1Char('\n')));
    return 0;
}

QJsonObject jogLatencyFromChild(const QString& benchPath, const QStringList& passThrough,
                                QString* error)
{
    QProcess child;
    child.setProcessChannelMode(QProcess::SeparateChannels);
    child.start(benchPath, QStringList{"--jog-latency", "--json"} + passThrough);
    // 50 presses take ~0.4 s each per model; generous, a hung child must not hang the run.
    if (!child.waitForFinished(600000)) {
        child.kill();
        child.waitForFinished(3000);
        *error = QStringLiteral("the jog latency run did not finish within 10 min");
        return {};
    }
    const QJsonObject out = QJsonDocument::fromJson(child.readAllStandardOutput()).object();
    if (child.exitStatus() != QProcess::NormalExit || child.exitCode() != 0 || out.isEmpty()) {
        *error = QStringLiteral("the jog latency run failed (exit %1): %2")
                     .arg(child.exitCode())
                     .arg(QString::fromUtf8(child.readAllStandardError()).trimmed());
        return {};
    }
    return out;
}

} // namespace stepdeck::bench
