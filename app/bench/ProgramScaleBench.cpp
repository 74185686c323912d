// stepdeck-bench --program-scale (ProgramScaleBench.h).
#include "ProgramScaleBench.h"
#include "BenchOutput.h"
#include "program/ProgramCheck.h"
#include "program/ProgramParser.h"
#include "protocols/Registry.h"
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <cmath>

namespace stepdeck::bench {

namespace {

struct ScaleFigures
{
    qint64 lines = 0;
    double parseSeconds = 0; // the one pass: parsed and checked as read
    double checkSeconds = 0; // the check again over the parsed Program (the run's start)
    qint64 peakKiB = 0;      // VmHWM while parsing and checking this size
    QString refusal;         // the first error, when the program was refused
};

// The process' peak resident set (VmHWM), in KiB; 0 where /proc does not say.
qint64 peakResidentKiB()
{
    QFile status(QStringLiteral("/proc/self/status"));
    if (!status.open(QIODevice::ReadOnly))
        return 0;
    for (const QByteArray& line : status.readAll().split('\n'))
        if (line.startsWith("VmHWM:"))
            return line.mid(6).trimmed().split(' ').value(0).toLongLong();
    return 0;
}

// Lets VmHWM start again from the present resident set (Linux: clear_refs "5").
void resetPeak()
{
    QFile refs(QStringLiteral("/proc/self/clear_refs"));
    if (refs.open(QIODevice::WriteOnly))
        refs.write("5");
}

program::MachineFacts benchFacts()
{
    program::MachineFacts facts;
    const ModelInfo* elab = findModel(QStringLiteral("elab"));
    machine::MachineController c;
    c.id = QStringLiteral("table");
    c.modelId = elab->id;
    facts.description.controllers << c;
    facts.capabilities.insert(c.id, elab->capabilities);
    facts.schemas.insert(c.id, elab->schema);
    const char* names[] = {"X", "Y", "Z"};
    for (int i = 0; i < 3; ++i) {
        machine::MachineAxis a;
        a.name = QLatin1String(names[i]);
        a.controller = c.id;
        a.axis = Axis::at(i);
        a.unit = machine::AxisUnit::Millimetre;
        a.stepsPerUnit = 100;
        a.softMinimum = i == 2 ? -100 : 0;
        a.softMaximum = i == 2 ? 10 : 1000;
        facts.description.axes << a;
        facts.knownPositions.insert(a.name, 0.0);
    }
    // The board's setup as written before a run (issue 30: its feed moves are contour streams
    // that tick below the start speed, here at the wire's 2100/s).
    ParameterValue start;
    for (Axis axis : elab->capabilities.axes)
        start.perAxis.insert(axis, 2401);
    facts.knownParameters[c.id].insert(QStringLiteral("start-speed"), start);
    return facts;
}

// A finishing pass over a 200 x 200 mm surface: rows of short G1 steps with Z following a
// wave, an arc every 50 lines, a rapid between rows.
bool writeProgram(const QString& path, qint64 lines)
{
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        return false;
    QByteArray chunk;
    chunk += "G21 G90 G17\nG0 Z5\nG0 X0 Y0\nG1 Z-1 F600\n";
    double x = 0, y = 0;
    for (qint64 i = 4; i < lines - 1; ++i) { // four lines of header, M2 last
        if (i % 2000 == 0) {
            y = std::fmod(y + 0.5, 200.0);
            x = 0;
            chunk += QByteArray("G0 X0 Y") + QByteArray::number(y, 'f', 3) + '\n';
        } else if (i % 50 == 0) {
            chunk += QByteArray("G2 X") + QByteArray::number(x + 0.2, 'f', 3) + " I0.1 J0\n";
            x += 0.2;
        } else {
            x = std::fmod(x + 0.1, 200.0);
            const double z = -1 - 0.5 * std::sin(x / 7.0) * std::cos(y / 11.0);
            chunk += QByteArray("G1 X") + QByteArray::number(x, 'f', 3) + " Z" +
                     QByteArray::number(z, 'f', 3) + '\n';
        }
        if (chunk.size() > (1 << 20)) {
            if (f.write(chunk) != chunk.size())
                return false;
            chunk.clear();
        }
    }
    chunk += "M2\n";
    return f.write(chunk) == chunk.size();
}

// The window's and the CLI's path (issue 29): the one pass over the file (parsed and checked
// as it is read), then the check again over the Program it gave (as ProgramRunner::start does,
// reading the file once more through the index).
ScaleFigures measure(const QString& path, qint64 lines)
{
    ScaleFigures out;
    out.lines = lines;
    resetPeak();
    const program::MachineFacts facts = benchFacts();
    const QStringList axes{QStringLiteral("X"), QStringLiteral("Y"), QStringLiteral("Z")};
    QElapsedTimer timer;
    timer.start();
    const program::ProgramCheckResult first =
        program::ProgramCheck::check(program::ProgramSource::file(path), axes, facts);
    out.parseSeconds = double(timer.nsecsElapsed()) / 1e9;
    if (!first.ok() || !first.program) {
        out.refusal = first.errors.value(0).text();
    } else {
        timer.restart();
        const program::ProgramCheckResult again =
            program::ProgramCheck::check(*first.program, facts);
        out.checkSeconds = double(timer.nsecsElapsed()) / 1e9;
        if (!again.ok())
            out.refusal = again.errors.value(0).text();
    }
    out.peakKiB = peakResidentKiB();
    return out;
}

QString rate(qint64 lines, double seconds)
{
    return seconds > 0 ? QString::number(qint64(double(lines) / seconds)) : QStringLiteral("-");
}

} // namespace

int programScaleBenchMain(const QStringList& args)
{
    if (!args.contains(QLatin1String("--program-scale")))
        return -1;
    const bool json = args.contains(QLatin1String("--json"));
    QList<qint64> sizes;
    for (const QString& a : args) {
        if (a.startsWith(QLatin1String("--")))
            continue;
        bool ok = false;
        const qint64 n = a.toLongLong(&ok);
        if (!ok || n < 10 || n > 100000000) {
            print(stderr, QStringLiteral("stepdeck-bench: bad size '%1' (10..100000000)").arg(a));
            return 2;
        }
        sizes << n;
    }
    if (sizes.isEmpty())
        sizes = {100000, 1000000, 10000000};
    QTemporaryDir dir;
    QJsonArray results;
    for (qint64 lines : std::as_const(sizes)) {
        const QString path = dir.filePath(QStringLiteral("scale.ngc"));
        if (!writeProgram(path, lines)) {
            print(stderr, QStringLiteral("stepdeck-bench: cannot write %1").arg(path));
            return 1;
        }
        const ScaleFigures f = measure(path, lines);
        QFile::remove(path);
        if (json) {
            results << QJsonObject{{"lines", f.lines},
                                   {"onePassLinesPerSecond",
                                    f.parseSeconds > 0 ? double(f.lines) / f.parseSeconds : 0.0},
                                   {"recheckLinesPerSecond",
                                    f.checkSeconds > 0 ? double(f.lines) / f.checkSeconds : 0.0},
                                   {"peakResidentMiB", double(f.peakKiB) / 1024.0},
                                   {"refusal", f.refusal}};
            continue;
        }
        print(stdout,
              QStringLiteral("program of %1 lines: check (one pass) %2 lines/s, check again "
                             "(run's start) %3 lines/s, peak resident %4 MiB%5")
                  .arg(f.lines)
                  .arg(rate(f.lines, f.parseSeconds), rate(f.lines, f.checkSeconds))
                  .arg(double(f.peakKiB) / 1024.0, 0, 'f', 1)
                  .arg(f.refusal.isEmpty() ? QString()
                                           : QStringLiteral(" (refused: %1)").arg(f.refusal)));
    }
    if (json)
        print(stdout, QString::fromUtf8(QJsonDocument(QJsonObject{{"programScale", results}})
                                            .toJson(QJsonDocument::Compact)));
    return 0;
}

} // namespace stepdeck::bench
