#include "SimScenario.h"
#include "protocols/elab/ElabCodec.h"
#include "protocols/elab/ElabSimulator.h"
#include "sim/Simulator.h"
#include <QCoreApplication>

namespace stepdeck::simapp {

namespace {
QString tr(const char* text)
{
    return QCoreApplication::translate("stepdeck-sim", text);
}

bool takeValue(const QStringList& args, int* i, QString* value, QString* error)
{
    const QString& arg = args.at(*i);
    const int eq = arg.indexOf(QLatin1Char('='));
    if (arg.startsWith(QLatin1String("--")) && eq > 0) {
        *value = arg.mid(eq + 1);
        return true;
    }
    if (*i + 1 >= args.size()) {
        *error = tr("option %1 needs a value").arg(arg);
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
bool parseLimit(const QString& text, QMap<Axis, LimitRange>* limits, QString* error)
{
    const int eq = text.indexOf(QLatin1Char('='));
    const auto axis = eq > 0 ? axisFromName(QStringView(text).left(eq)) : std::nullopt;
    const QStringList range = text.mid(eq + 1).split(QLatin1Char(':'));
    bool okMin = false;
    bool okMax = false;
    LimitRange limit;
    if (range.size() == 2) {
        limit.minimum = range[0].toLongLong(&okMin);
        limit.maximum = range[1].toLongLong(&okMax);
    }
    if (!axis || !okMin || !okMax || limit.minimum >= limit.maximum) {
        *error = tr("--limit expects AXIS=MIN:MAX with MIN < MAX, e.g. X=-1000:1000, got '%1'")
                     .arg(text);
        return false;
    }
    limits->insert(*axis, limit);
    return true;
}

bool parsePosition(const QString& text, QMap<Axis, qint64>* positions, QString* error)
{
    const int eq = text.indexOf(QLatin1Char('='));
    const auto axis = eq > 0 ? axisFromName(QStringView(text).left(eq)) : std::nullopt;
    bool ok = false;
    const qint64 steps = text.mid(eq + 1).toLongLong(&ok);
    if (!axis || !ok) {
        *error = tr("--position expects AXIS=STEPS, e.g. X=500, got '%1'").arg(text);
        return false;
    }
    positions->insert(*axis, steps);
    return true;
}
} // namespace

bool parseScenario(const QStringList& args, SimScenario* scenario, QString* error)
{
    SimScenario s;
    for (int i = 0; i < args.size(); ++i) {
        const QString name = optionName(args.at(i));
        QString value;
        if (name == QLatin1String("--help") || name == QLatin1String("-h")) {
            s.help = true;
        } else if (name == QLatin1String("--version") || name == QLatin1String("-v")) {
            s.version = true;
        } else if (name == QLatin1String("--pace")) {
            s.pace = true;
        } else if (name == QLatin1String("--setup-complete")) {
            s.setupComplete = true;
        } else if (name == QLatin1String("--model")) {
            if (!takeValue(args, &i, &s.model, error))
                return false;
        } else if (name == QLatin1String("--drives")) {
            if (!takeValue(args, &i, &value, error))
                return false;
            for (const QString& part : value.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
                bool ok = false;
                const int address = part.toInt(&ok);
                if (!ok || address < 0) {
                    *error = tr("--drives expects addresses like 1,2,3, got '%1'").arg(value);
                    return false;
                }
                s.drives << address;
            }
        } else if (name == QLatin1String("--temperature")) {
            bool ok = false;
            if (!takeValue(args, &i, &value, error))
                return false;
            s.temperature = value.toInt(&ok);
            if (!ok) {
                *error = tr("--temperature expects whole degrees Celsius, got '%1'").arg(value);
                return false;
            }
        } else if (name == QLatin1String("--limit")) {
            if (!takeValue(args, &i, &value, error) || !parseLimit(value, &s.limits, error))
                return false;
        } else if (name == QLatin1String("--position")) {
            if (!takeValue(args, &i, &value, error) || !parsePosition(value, &s.positions, error))
                return false;
        } else {
            *error = tr("unknown argument '%1' (try --help)").arg(args.at(i));
            return false;
        }
    }
    *scenario = s;
    return true;
}

QString simUsage()
{
    return tr("Usage: stepdeck-sim [--model MODEL] [--drives 1,2,3] [OPTION]...\n"
              "\n"
              "Simulates a controller on a new pseudo-terminal. The first line on stdout is the\n"
              "terminal's path; open it with `stepdeck-cli --port PATH ...` or the GUI. Serves\n"
              "until SIGINT/SIGTERM.\n"
              "\n"
              "Options:\n"
              "  --model MODEL      controller model (default elab)\n"
              "  --drives LIST      bus addresses of the simulated drives (multi-drive models)\n"
              "  --pace             release replies at the line's character rate (57600 8N2\n"
              "                     for elab), so timing is like a real serial line\n"
              "  --setup-complete   start with start/max speed and acceleration written\n"
              "                     (the board powers on with setup incomplete)\n"
              "  --temperature C    board temperature (above 50 sets over-temperature)\n"
              "  --limit AXIS=MIN:MAX   limit switches of an axis at these positions\n"
              "  --position AXIS=STEPS  where the carriage stands at power-on\n"
              "  --help, --version\n");
}

bool applyScenario(const SimScenario& scenario, Simulator* simulator, QString* error)
{
    auto* elabSim = qobject_cast<elab::ElabSimulator*>(simulator);
    const bool needsModelApi = scenario.setupComplete || scenario.temperature ||
                               !scenario.limits.isEmpty() || !scenario.positions.isEmpty();
    if (!elabSim) {
        if (needsModelApi) {
            *error = tr("--setup-complete, --temperature, --limit and --position are only "
                        "supported for model elab");
            return false;
        }
        return true;
    }
    if (scenario.setupComplete) {
        // Through the protocol itself, exactly as a host would do it (manual: Setup Befehle);
        // the simulator is not attached yet, so its ACKs go nowhere.
        using namespace elab;
        const Triple<quint16> start{100, 100, 100};
        const Triple<quint16> max{5000, 5000, 5000};
        const Triple<quint16> accel{1000, 1000, 1000};
        const bool paced = simulator->options().paceOutput;
        simulator->setPacing(false, simulator->options().line);
        elabSim->receive(encode::ramp(RampKind::StartSpeed, start) +
                         encode::ramp(RampKind::MaxSpeed, max) +
                         encode::ramp(RampKind::Acceleration, accel));
        simulator->setPacing(paced, simulator->options().line);
    }
    if (scenario.temperature)
        elabSim->setTemperature(*scenario.temperature);
    for (auto it = scenario.limits.cbegin(); it != scenario.limits.cend(); ++it) {
        if (it.key() == Axis::U) {
            *error = tr("model elab has no axis U");
            return false;
        }
        elabSim->setLimitPositions(it.key(), it.value().minimum, it.value().maximum);
    }
    for (auto it = scenario.positions.cbegin(); it != scenario.positions.cend(); ++it) {
        if (it.key() == Axis::U) {
            *error = tr("model elab has no axis U");
            return false;
        }
        elabSim->setPosition(it.key(), it.value());
    }
    return true;
}

} // namespace stepdeck::simapp
