// The soak and replug modes of stepdeck-bench. A soak runs each model in a child process of
// its own (--soak-child), so a crash of the stack under test is counted, not fatal, and a
// run that stops making progress is killed and counted as a hang.
#include "SoakMain.h"
#include "BenchOutput.h"
#include "MachineSoak.h"
#include "Replug.h"
#include "Soak.h"
#include "model/NumberParsing.h"
#include "protocols/Registry.h"
#include <QJsonArray>
#include <QJsonDocument>
#include <QProcess>
#include <cstdio>
#include <limits>

namespace stepdeck::bench {

namespace {
struct Options
{
    int soak = 0;
    int replug = 0;
    QString model; // empty: every registered model
    quint32 seed = 1;
    bool json = false;
    bool child = false;
    bool machine = false; // --soak N --machine: one machine of an E-LAB and a Nanotec
    int drives = 0;       // --drives N: a bus of N drives (multi-drive models; issue 32)
};

// Returns false with *error on a malformed value; unknown arguments are left to main.cpp.
bool parse(const QStringList& args, Options* o, QString* error)
{
    for (int i = 0; i < args.size(); ++i) {
        const QString& a = args.at(i);
        const auto value = [&]() { return i + 1 < args.size() ? args.at(++i) : QString(); };
        qint64 n = 0;
        if (a == QLatin1String("--soak") || a == QLatin1String("--replug")) {
            if (numbers::parseInteger(value(), 1, 10'000'000, &n) != NumberError::None) {
                *error = QStringLiteral("%1 needs a count from 1 to 10000000").arg(a);
                return false;
            }
            (a == QLatin1String("--soak") ? o->soak : o->replug) = int(n);
        } else if (a == QLatin1String("--model")) {
            o->model = value();
        } else if (a == QLatin1String("--seed")) {
            if (numbers::parseInteger(value(), 0, std::numeric_limits<quint32>::max(), &n) !=
                NumberError::None) {
                *error = QStringLiteral("--seed needs a number from 0 to 4294967295");
                return false;
            }
            o->seed = quint32(n);
        } else if (a == QLatin1String("--json")) {
            o->json = true;
        } else if (a == QLatin1String("--soak-child")) {
            o->child = true;
        } else if (a == QLatin1String("--machine")) {
            o->machine = true;
        } else if (a == QLatin1String("--drives")) {
            if (numbers::parseInteger(value(), 1, Axis::kMaxCount, &n) != NumberError::None) {
                *error = QStringLiteral("--drives needs a count from 1 to %1").arg(Axis::kMaxCount);
                return false;
            }
            o->drives = int(n);
        } else {
            *error = QStringLiteral("unknown argument '%1'").arg(a);
            return false;
        }
    }
    return true;
}

QList<const ModelInfo*> selected(const Options& o, QString* error)
{
    QList<const ModelInfo*> out;
    for (const ModelInfo& m : models()) {
        if (o.model.isEmpty() || m.id == o.model)
            out << &m;
    }
    if (out.isEmpty())
        *error = QStringLiteral("no soak model '%1'").arg(o.model);
    return out;
}

// Runs one model's soak in a child process and reads its figures.
// (model: nullptr for the machine soak.)
SoakFigures soakInChild(const QString& program, const ModelInfo* model, const Options& o)
{
    QProcess child;
    child.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    QStringList args{"--soak-child", "--soak", QString::number(o.soak), "--seed",
                     QString::number(o.seed)};
    args << (model ? QStringList{"--model", model->id} : QStringList{"--machine"});
    if (o.drives > 0)
        args << QStringLiteral("--drives") << QString::number(o.drives);
    child.start(program, args);
    // Generous: a command takes well under a second even with its faults.
    const int boundMs =
        int(qMin<qint64>(std::numeric_limits<int>::max(), 60000 + qint64(o.soak) * 2000));
    const bool finished = child.waitForFinished(boundMs);
    SoakFigures fig;
    fig.model = model ? model->id : QStringLiteral("machine");
    fig.commands = o.soak;
    fig.seed = o.seed;
    if (!finished) {
        child.kill();
        child.waitForFinished();
        fig.hangs = 1; // the run itself stopped making progress
        return fig;
    }
    const QList<QByteArray> lines = child.readAllStandardOutput().trimmed().split('\n');
    const QJsonDocument doc = QJsonDocument::fromJson(lines.last());
    if (child.exitStatus() != QProcess::NormalExit || !doc.isObject()) {
        fig.crashes = 1;
        return fig;
    }
    return SoakFigures::fromJson(doc.object());
}

int soak(const QString& program, const Options& o)
{
    QString error;
    QList<const ModelInfo*> chosen = selected(o, &error);
    if (o.machine) {
        if (!o.model.isEmpty()) {
            print(stderr, QStringLiteral("stepdeck-bench: --machine soaks its own machine of an "
                                         "E-LAB and a Nanotec; no --model with it"));
            return 2;
        }
        chosen = {nullptr};
    }
    if (chosen.isEmpty()) {
        print(stderr, QStringLiteral("stepdeck-bench: %1").arg(error));
        return 2;
    }
    if (o.drives > 0 &&
        (chosen.size() != 1 || !chosen.first() || !chosen.first()->capabilities.multiDrive)) {
        print(stderr, QStringLiteral("stepdeck-bench: --drives N needs --model of a bus of "
                                     "drives (nanotec)"));
        return 2;
    }
    const auto progress = [&](const QString& line) {
        if (!o.json)
            print(stderr, line);
    };
    if (o.child) { // one model, in this process; the parent reads the last line
        const SoakFigures fig = o.machine
                                    ? runMachineSoak(o.soak, o.seed, progress)
                                    : runSoak(*chosen.first(), o.soak, o.seed, o.drives, progress);
        print(stdout,
              QString::fromUtf8(QJsonDocument(fig.toJson()).toJson(QJsonDocument::Compact)));
        return 0;
    }
    QJsonArray all;
    bool clean = true;
    for (const ModelInfo* m : chosen) {
        const SoakFigures fig = soakInChild(program, m, o);
        clean = clean && fig.clean();
        all.append(fig.toJson());
        if (!o.json)
            print(stdout, fig.toText());
    }
    if (o.json)
        print(stdout, QString::fromUtf8(QJsonDocument(QJsonObject{{"soak", all}, {"clean", clean}})
                                            .toJson(QJsonDocument::Compact)));
    return clean ? 0 : 1;
}

int replug(const Options& o)
{
    QString error;
    const QList<const ModelInfo*> chosen = selected(o, &error);
    if (chosen.isEmpty()) {
        print(stderr, QStringLiteral("stepdeck-bench: %1").arg(error));
        return 2;
    }
    QJsonArray all;
    for (const ModelInfo* m : chosen) {
        const ReplugFigures fig = runReplug(*m, o.replug, o.seed, [&](const QString& line) {
            if (!o.json)
                print(stderr, line);
        });
        all.append(fig.toJson());
        if (!o.json)
            print(stdout, fig.toText());
    }
    if (o.json)
        print(stdout,
              QString::fromUtf8(
                  QJsonDocument(QJsonObject{{"replug", all}}).toJson(QJsonDocument::Compact)));
    return 0;
}
} // namespace

int soakMain(const QString& program, const QStringList& args)
{
    if (!args.contains(QStringLiteral("--soak")) && !args.contains(QStringLiteral("--replug")))
        return -1;
    Options o;
    QString error;
    if (!parse(args, &o, &error)) {
        print(stderr, QStringLiteral("stepdeck-bench: %1").arg(error));
        return 2;
    }
    if (o.soak > 0 && o.replug > 0) {
        print(stderr, QStringLiteral("stepdeck-bench: give --soak or --replug, not both"));
        return 2;
    }
    return o.soak > 0 ? soak(program, o) : replug(o);
}

} // namespace stepdeck::bench
