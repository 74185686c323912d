#include "SimScenario.h"
#include "model/NumberParsing.h"
#include "protocols/Registry.h"
#include "sim/Simulator.h"
#include <QCoreApplication>
#include <QtMath>
#include <limits>

namespace stepdeck::simapp {

namespace {
bool takeValue(const QStringList& args, int* i, QString* value, QString* error)
{
    const QString& arg = args.at(*i);
    const int eq = arg.indexOf(QLatin1Char('='));
    if (arg.startsWith(QLatin1String("--")) && eq > 0) {
        *value = arg.mid(eq + 1);
        return true;
    }
    if (*i + 1 >= args.size()) {
        *error = SimText::tr("option %1 needs a value").arg(arg);
        return false;
    }
    *value = args.at(++*i);
    return true;
}

QString optionName(const QString& arg)
{
    const int eq = arg.indexOf(QLatin1Char('='));
    return eq > 0 ? arg.left(eq) : arg;
}

// "X=-1000:1000"
bool parseLimit(const QString& text, QMap<Axis, SwitchRange>* limits, QString* error)
{
    const int eq = text.indexOf(QLatin1Char('='));
    const auto axis = eq > 0 ? axisFromName(QStringView(text).left(eq)) : std::nullopt;
    const QStringList range = text.mid(eq + 1).split(QLatin1Char(':'));
    bool okMin = false;
    bool okMax = false;
    SwitchRange limit;
    if (range.size() == 2) {
        okMin = numbers::parseInteger(range[0], &limit.minimum) == NumberError::None;
        okMax = numbers::parseInteger(range[1], &limit.maximum) == NumberError::None;
    }
    if (!axis || !okMin || !okMax || limit.minimum >= limit.maximum) {
        *error =
            SimText::tr("--limit expects AXIS=MIN:MAX with MIN < MAX, e.g. X=-1000:1000, got '%1'")
                .arg(text);
        return false;
    }
    limits->insert(*axis, limit);
    return true;
}

bool parsePosition(const QString& text, QMap<Axis, qint64>* positions, QString* error,
                   const QString& option = QStringLiteral("--position"))
{
    const int eq = text.indexOf(QLatin1Char('='));
    const auto axis = eq > 0 ? axisFromName(QStringView(text).left(eq)) : std::nullopt;
    qint64 steps = 0;
    const bool ok = numbers::parseInteger(text.mid(eq + 1), &steps) == NumberError::None;
    if (!axis || !ok) {
        *error = SimText::tr("%1 expects AXIS=STEPS, e.g. X=500, got '%2'").arg(option, text);
        return false;
    }
    positions->insert(*axis, steps);
    return true;
}

// "--drop 0.01": a probability 0..1, decimal.
bool parseProbability(const QString& option, const QString& text, double* value, QString* error)
{
    if (numbers::parseReal(text, value) != NumberError::None || *value < 0 || *value > 1) {
        *error = SimText::tr("%1 expects a probability from 0 to 1 (e.g. 0.01), got '%2'")
                     .arg(option, text);
        return false;
    }
    return true;
}

// --drop, --corrupt, --noise, --freeze-after, --seed; *matched tells whether name was one.
bool parseFaultOption(const QString& name, const QStringList& args, int* i, SimScenario* s,
                      bool* matched, QString* error)
{
    static const QStringList names{"--drop", "--corrupt", "--noise", "--freeze-after", "--seed"};
    *matched = names.contains(name);
    QString value;
    if (!*matched)
        return true;
    if (!takeValue(args, i, &value, error))
        return false;
    if (name == QLatin1String("--drop"))
        return parseProbability(name, value, &s->dropProbability, error);
    if (name == QLatin1String("--corrupt"))
        return parseProbability(name, value, &s->corruptProbability, error);
    if (name == QLatin1String("--noise")) {
        if (numbers::parseReal(value, &s->noiseBytesPerSecond) != NumberError::None ||
            s->noiseBytesPerSecond < 0 || s->noiseBytesPerSecond > 100000) {
            *error = SimText::tr("--noise expects bytes per second from 0 to 100000, got '%1'")
                         .arg(value);
            return false;
        }
        return true;
    }
    if (name == QLatin1String("--freeze-after")) {
        if (numbers::parseInteger(value, 0, std::numeric_limits<int>::max(), &s->freezeAfterMs) !=
            NumberError::None) {
            *error =
                SimText::tr("--freeze-after expects milliseconds (0 or more), got '%1'").arg(value);
            return false;
        }
        return true;
    }
    qint64 seed = 0;
    if (numbers::parseInteger(value, 0, std::numeric_limits<quint32>::max(), &seed) !=
        NumberError::None) {
        *error = SimText::tr("--seed expects a number from 0 to %1, got '%2'")
                     .arg(std::numeric_limits<quint32>::max())
                     .arg(value);
        return false;
    }
    s->seed = quint32(seed);
    return true;
}

// "1,3": bus addresses (--no-encoder).
bool parseAddresses(const QString& option, const QString& text, QList<int>* out, QString* error)
{
    for (const QString& part : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        int address = 0;
        if (numbers::parseInt(part, 1, 254, &address) != NumberError::None) {
            *error = SimText::tr("%1 expects bus addresses like 1,3, got '%2'").arg(option, text);
            return false;
        }
        *out << address;
    }
    return true;
}

// Closed loop (Nanotec manual 8.1): --no-encoder LIST, --calibration-ms MS; *matched tells
// whether name was one.
bool parseClosedLoopOption(const QString& name, const QStringList& args, int* i,
                           SimulatorScenario* s, bool* matched, QString* error)
{
    *matched = name == QLatin1String("--no-encoder") || name == QLatin1String("--calibration-ms");
    QString value;
    if (!*matched)
        return true;
    if (!takeValue(args, i, &value, error))
        return false;
    if (name == QLatin1String("--no-encoder"))
        return parseAddresses(name, value, &s->drivesWithoutEncoder, error);
    int ms = 0;
    if (numbers::parseInt(value, 20, 3600000, &ms) != NumberError::None) {
        *error = SimText::tr("--calibration-ms expects milliseconds from 20 to 3600000, got '%1'")
                     .arg(value);
        return false;
    }
    s->calibrationMs = ms;
    return true;
}

bool parseSpeed(const QString& text, std::optional<double>* speed, QString* error)
{
    double value = 0;
    if (numbers::parseReal(text, &value) != NumberError::None || !qIsFinite(value) || value < 1 ||
        value > 1e7) {
        *error =
            SimText::tr("--speed expects units per second from 1 to 10000000, got '%1'").arg(text);
        return false;
    }
    *speed = value;
    return true;
}
} // namespace

namespace {
// --input N=LEVEL: "5=1", "6=0" (issue 28: the part sensor an example program waits for).
bool parseInput(const QString& value, QMap<int, bool>* inputs, QString* error)
{
    const QStringList parts = value.split(QLatin1Char('='));
    int number = 0;
    int level = 0;
    if (parts.size() != 2 ||
        numbers::parseInt(parts.at(0), 1, 9999, &number) != NumberError::None ||
        numbers::parseInt(parts.at(1), 0, 1, &level) != NumberError::None) {
        *error = SimText::tr("--input expects NUMBER=0 or NUMBER=1, got '%1'").arg(value);
        return false;
    }
    inputs->insert(number, level == 1);
    return true;
}

// --machine FILE and --out FILE (issue 19, app/sim/SimMachine.h).
bool parseMachineOption(const QString& name, const QStringList& args, int* i, SimScenario* s,
                        bool* matched, QString* error)
{
    *matched = name == QLatin1String("--machine") || name == QLatin1String("--out");
    if (!*matched)
        return true;
    return takeValue(args, i, name == QLatin1String("--machine") ? &s->machineFile : &s->machineOut,
                     error);
}
} // namespace

bool parseScenario(const QStringList& args, SimScenario* scenario, QString* error)
{
    SimScenario s;
    for (int i = 0; i < args.size(); ++i) {
        const QString name = optionName(args.at(i));
        QString value;
        bool fault = false;
        bool closedLoop = false;
        bool machineFile = false;
        if (!parseFaultOption(name, args, &i, &s, &fault, error) ||
            !parseClosedLoopOption(name, args, &i, &s.machine, &closedLoop, error) ||
            !parseMachineOption(name, args, &i, &s, &machineFile, error))
            return false;
        if (fault || closedLoop || machineFile)
            continue;
        if (name == QLatin1String("--help") || name == QLatin1String("-h")) {
            s.help = true;
        } else if (name == QLatin1String("--version") || name == QLatin1String("-v")) {
            s.version = true;
        } else if (name == QLatin1String("--pace")) {
            s.pace = true;
        } else if (name == QLatin1String("--setup-complete")) {
            s.machine.setupComplete = true;
        } else if (name == QLatin1String("--model")) {
            if (!takeValue(args, &i, &s.model, error))
                return false;
        } else if (name == QLatin1String("--drives")) {
            if (!takeValue(args, &i, &value, error))
                return false;
            for (const QString& part : value.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
                int address = 0;
                if (numbers::parseInt(part, 0, 255, &address) != NumberError::None) {
                    *error =
                        SimText::tr("--drives expects addresses like 1,2,3, got '%1'").arg(value);
                    return false;
                }
                s.drives << address;
            }
        } else if (name == QLatin1String("--temperature")) {
            if (!takeValue(args, &i, &value, error))
                return false;
            int celsius = 0;
            if (numbers::parseInt(value, -273, 1000, &celsius) != NumberError::None) {
                *error =
                    SimText::tr("--temperature expects whole degrees Celsius, got '%1'").arg(value);
                return false;
            }
            s.machine.temperature = celsius;
        } else if (name == QLatin1String("--limit")) {
            if (!takeValue(args, &i, &value, error) || !parseLimit(value, &s.machine.limits, error))
                return false;
        } else if (name == QLatin1String("--position")) {
            if (!takeValue(args, &i, &value, error) ||
                !parsePosition(value, &s.machine.positions, error))
                return false;
        } else if (name == QLatin1String("--end-switch")) {
            if (!takeValue(args, &i, &value, error) ||
                !parsePosition(value, &s.machine.endSwitches, error, name))
                return false;
        } else if (name == QLatin1String("--speed")) {
            if (!takeValue(args, &i, &value, error) || !parseSpeed(value, &s.machine.speed, error))
                return false;
        } else if (name == QLatin1String("--input")) {
            if (!takeValue(args, &i, &value, error) || !parseInput(value, &s.machine.inputs, error))
                return false;
        } else if (name == QLatin1String("--silent")) {
            s.machine.silent = true;
        } else if (name == QLatin1String("--garbage")) {
            s.machine.garbage = true;
        } else {
            *error = SimText::tr("unknown argument '%1' (try --help)").arg(args.at(i));
            return false;
        }
    }
    if (!s.machineOut.isEmpty() && s.machineFile.isEmpty()) {
        *error = SimText::tr("--out needs --machine");
        return false;
    }
    *scenario = s;
    return true;
}

QString simUsage()
{
    return SimText::tr(
               "Usage: stepdeck-sim [--model MODEL] [--drives 1,2,3] [OPTION]...\n"
               "\n"
               "Simulates a controller on a new pseudo-terminal. The first line on stdout is the\n"
               "terminal's path; open it with `stepdeck-cli --port PATH ...` or the GUI. Serves\n"
               "until SIGINT/SIGTERM.\n"
               "\n"
               "Options:\n"
               "  --model MODEL      controller model: %1 (default %2)\n"
               "  --drives LIST      bus addresses of the simulated drives (multi-drive models)\n"
               "  --pace             release replies at the line's character rate (%3 for\n"
               "                     %2), so timing is like a real serial line\n"
               "  --setup-complete   start with start/max speed and acceleration written\n"
               "                     (the board powers on with setup incomplete)\n"
               "  --temperature C    board temperature (above 50 sets over-temperature)\n"
               "  --limit AXIS=MIN:MAX   limit switches of an axis at these positions\n"
               "  --input N=LEVEL    a digital input the machine drives, 1 (high) or 0 (low);\n"
               "                     repeat for several (emis: inputs 5..8, e.g. a part sensor)\n"
               "  --position AXIS=STEPS  where the carriage stands at power-on (emis: steps\n"
               "                     from the reference switch; laser-axis: units from the\n"
               "                     home switch)\n"
               "\n"
               "nanotec only (closed loop, manual 8.1):\n"
               "  --no-encoder LIST  drives (addresses) without encoder: their calibration and\n"
               "                     closed-loop reference runs fail with a position error\n"
               "  --calibration-ms MS  how long a calibration run (!101) takes (default 5000)\n"
               "\n"
               "laser-axis only:\n"
               "  --speed UNITS      axis speed in position units per second (default 10000)\n"
               "  --end-switch AXIS=POS  the end switch of an axis at this position\n"
               "  --silent           the axes move but never send a status frame\n"
               "  --garbage          a malformed line before every status frame\n"
               "\n"
               "Faults (random, reproducible with the same --seed and the same traffic):\n"
               "  --drop P           each reply is lost with probability P (0..1, e.g. 0.01)\n"
               "  --corrupt P        each reply has one random byte replaced with probability P\n"
               "  --noise N          N random bytes per second (mean) sent unasked, between and\n"
               "                     inside replies\n"
               "  --freeze-after MS  answer for MS ms from the first reply on, then nothing at\n"
               "                     all while the terminal stays open (a frozen peer)\n"
               "  --seed N           seed of the fault generator (default 1)\n"
               "\n"
               "Machines (docs/machines.md):\n"
               "  --machine FILE     one simulator per controller of the machine file, each on\n"
               "                     its own pseudo-terminal; the first line on stdout is a\n"
               "                     copy of the file (compact JSON) whose ports point at them.\n"
               "                     --pace, --setup-complete and the faults apply to each\n"
               "  --out FILE         also write that copy to FILE, for stepdeck-cli --machine\n"
               "  --help, --version\n")
        .arg(modelIds().join(QStringLiteral(", ")), models().first().id,
             models().first().line.text());
}

void applyFaults(const SimScenario& scenario, Simulator* simulator)
{
    simulator->faults().dropProbability = scenario.dropProbability;
    simulator->faults().corruptProbability = scenario.corruptProbability;
    simulator->setNoise(scenario.noiseBytesPerSecond);
    simulator->freezeAfter(scenario.freezeAfterMs);
}

namespace {
// The command-line name of each machine option, for the refusals.
QString optionNames(ScenarioOptions options)
{
    static const QList<QPair<ScenarioOption, const char*>> names{
        {ScenarioOption::SetupComplete, "--setup-complete"},
        {ScenarioOption::Temperature, "--temperature"},
        {ScenarioOption::Limits, "--limit"},
        {ScenarioOption::Positions, "--position"},
        {ScenarioOption::Speed, "--speed"},
        {ScenarioOption::EndSwitches, "--end-switch"},
        {ScenarioOption::Silent, "--silent"},
        {ScenarioOption::Garbage, "--garbage"},
        {ScenarioOption::NoEncoder, "--no-encoder"},
        {ScenarioOption::CalibrationMs, "--calibration-ms"},
        {ScenarioOption::Inputs, "--input"}};
    QStringList out;
    for (const auto& [option, name] : names) {
        if (options.testFlag(option))
            out << QLatin1String(name);
    }
    return out.join(QStringLiteral(", "));
}
} // namespace

bool applyScenario(const SimScenario& scenario, const ModelInfo& model, Simulator* simulator,
                   QString* error)
{
    // Inputs are every simulator's own (Simulator::settableInputs), not the model's scenario.
    const ScenarioOptions unsupported = scenario.machine.used() & ~model.scenario.options &
                                        ~ScenarioOptions(ScenarioOption::Inputs);
    if (unsupported) {
        *error =
            SimText::tr("%1: not supported for model %2").arg(optionNames(unsupported), model.id);
        return false;
    }
    for (Axis axis : scenario.machine.axes()) {
        if (!model.capabilities.axes.contains(axis)) {
            *error = SimText::tr("model %1 has no axis %2").arg(model.id, axisName(axis));
            return false;
        }
    }
    if (model.scenario.apply && !model.scenario.apply(scenario.machine, simulator, error))
        return false;
    for (auto it = scenario.machine.inputs.cbegin(); it != scenario.machine.inputs.cend(); ++it) {
        if (!simulator->setSettableInput(it.key(), it.value())) {
            QStringList settable;
            for (int n : simulator->settableInputs())
                settable << QString::number(n);
            *error =
                settable.isEmpty()
                    ? SimText::tr("--input: model %1 has no inputs the machine sets").arg(model.id)
                    : SimText::tr("--input %1: model %2 lets the machine set inputs %3")
                          .arg(it.key())
                          .arg(model.id, settable.join(QStringLiteral(", ")));
            return false;
        }
    }
    return true;
}

} // namespace stepdeck::simapp
