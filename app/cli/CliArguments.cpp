#include "CliArguments.h"
#include "CliOutput.h"
#include "model/NumberParsing.h"
#include <QCoreApplication>
#include <limits>

namespace stepdeck::cli {

namespace {
QString tr(const char* text)
{
    return QCoreApplication::translate("stepdeck-cli", text);
}

// "--name VALUE" or "--name=VALUE" at args[*i]; advances *i past the value.
bool optionValue(const QStringList& args, int* i, const QString& name, QString* value,
                 QString* error)
{
    const QString& arg = args.at(*i);
    if (arg.startsWith(name + QLatin1Char('='))) {
        *value = arg.mid(name.size() + 1);
        return true;
    }
    if (*i + 1 >= args.size()) {
        *error = tr("option %1 needs a value").arg(name);
        return false;
    }
    *i += 1;
    *value = args.at(*i);
    return true;
}

bool isOption(const QString& arg, const QString& name)
{
    return arg == name || arg.startsWith(name + QLatin1Char('='));
}

// Parse: (QStringView text, T* value) -> NumberError. A failure is an Outcome whose message
// does not name the command yet.
template <typename T, typename Parse>
Outcome parseAxisAssignments(const QStringList& args, const QList<Axis>& axes, QMap<Axis, T>* out,
                             Parse parse)
{
    QMap<Axis, T> result;
    for (const QString& arg : args) {
        const int eq = arg.indexOf(QLatin1Char('='));
        const auto axis = eq > 0 ? axisFromName(QStringView(arg).left(eq)) : std::nullopt;
        if (!axis)
            return Outcome::usage(tr("expected AXIS=VALUE (e.g. X=100), got '%1'").arg(arg));
        if (!axes.contains(*axis))
            return Outcome::usage(tr("this machine has no axis %1").arg(axisName(*axis)));
        if (result.contains(*axis))
            return Outcome::usage(tr("axis %1 given twice").arg(axisName(*axis)));
        T value{};
        const QString text = arg.mid(eq + 1);
        switch (parse(QStringView(text), &value)) {
        case NumberError::None:
            break;
        case NumberError::Malformed:
            return Outcome::usage(
                tr("%1: '%2' is not a decimal number").arg(axisName(*axis), text));
        case NumberError::NonFinite:
            return Outcome::usage(tr("%1: '%2' is not a finite number").arg(axisName(*axis), text));
        case NumberError::OutOfRange:
            return Outcome::failure(ExitInvalidValue,
                                    tr("%1: '%2' is out of range").arg(axisName(*axis), text));
        }
        result.insert(*axis, value);
    }
    if (result.isEmpty())
        return Outcome::usage(tr("no axis given (e.g. X=100 Y=0 Z=-50)"));
    *out = result;
    return Outcome::success();
}

Outcome named(const QString& command, Outcome outcome)
{
    if (!outcome.ok())
        outcome.message = tr("%1: %2").arg(command, outcome.message);
    return outcome;
}
} // namespace

namespace {
// Global options that carry a value. Returns false with *error set on a bad value; *matched
// tells whether arg was one of them at all.
bool parseValueOption(const QStringList& argv, int* i, CliOptions* o, bool* matched, QString* error)
{
    const QString& arg = argv.at(*i);
    const QString name = arg.section(QLatin1Char('='), 0, 0);
    static const QStringList names{"--model",   "--port",       "--address",        "--axes",
                                   "--timeout", "--reset-line", "--arrival-timeout"};
    *matched = names.contains(name);
    QString value;
    if (!*matched || !optionValue(argv, i, name, &value, error))
        return !*matched;
    if (name == QLatin1String("--model")) {
        o->model = value;
    } else if (name == QLatin1String("--port")) {
        o->port = value;
    } else if (name == QLatin1String("--axes")) {
        return parseAxisMap(value, &o->axisAddresses, error);
    } else if (name == QLatin1String("--reset-line")) {
        const std::optional<LineSettings::ResetLine> line = resetLineFromName(value);
        if (!line) {
            *error = tr("--reset-line needs rts or dtr, got '%1'").arg(value);
            return false;
        }
        o->resetLine = *line;
    } else if (name == QLatin1String("--address")) {
        int n = 0;
        if (numbers::parseInt(value, 0, std::numeric_limits<int>::max(), &n) != NumberError::None) {
            *error = tr("--address needs a non-negative number, got '%1'").arg(value);
            return false;
        }
        o->address = n;
    } else if (name == QLatin1String("--arrival-timeout")) {
        if (numbers::parseInt(value, 1, std::numeric_limits<int>::max(), &o->arrivalTimeoutMs) !=
            NumberError::None) {
            *error = tr("--arrival-timeout needs a positive number of milliseconds");
            return false;
        }
    } else {
        if (numbers::parseInt(value, 1, std::numeric_limits<int>::max(), &o->connectTimeoutMs) !=
            NumberError::None) {
            *error = tr("--timeout needs a positive number of milliseconds");
            return false;
        }
    }
    return true;
}
} // namespace

bool parseArguments(const QStringList& argv, CliOptions* options, QString* error)
{
    CliOptions o;
    for (int i = 0; i < argv.size(); ++i) {
        const QString& arg = argv.at(i);
        bool matched = false;
        if (arg == QLatin1String("--help") || arg == QLatin1String("-h")) {
            o.help = true;
        } else if (arg == QLatin1String("--version")) {
            o.version = true;
        } else if (arg == QLatin1String("--json")) {
            o.json = true;
        } else if (arg == QLatin1String("--setup-defaults")) {
            o.setupDefaults = true;
        } else if (arg == QLatin1String("--verbose") || arg == QLatin1String("-v")) {
            o.verbose = true;
        } else if (!parseValueOption(argv, &i, &o, &matched, error)) {
            return false;
        } else if (matched) {
            continue;
        } else if (o.command.isEmpty() && !arg.startsWith(QLatin1String("--"))) {
            o.command = arg;
        } else if (o.command.isEmpty()) {
            *error = tr("unknown option '%1' (try --help)").arg(arg);
            return false;
        } else {
            o.args << arg; // the command's own arguments and options
        }
    }
    if (o.address && !o.axisAddresses.isEmpty()) {
        *error = tr("give either --address or --axes, not both");
        return false;
    }
    if (o.command.isEmpty() && !o.help && !o.version) {
        *error = tr("no command given (try --help)");
        return false;
    }
    *options = o;
    return true;
}

bool takeFlag(QStringList* args, const QString& flag)
{
    return args->removeAll(flag) > 0;
}

std::optional<QString> takeOption(QStringList* args, const QString& option, QString* error)
{
    for (int i = 0; i < args->size(); ++i) {
        if (!isOption(args->at(i), option))
            continue;
        QString value;
        int end = i;
        if (!optionValue(*args, &end, option, &value, error))
            return std::nullopt;
        args->erase(args->begin() + i, args->begin() + end + 1);
        return value;
    }
    return std::nullopt;
}

QString unknownOption(const QStringList& args)
{
    for (const QString& arg : args) {
        if (arg.startsWith(QLatin1String("--")))
            return tr("unknown option '%1' (try --help)").arg(arg);
    }
    return {};
}

Outcome parseAxisIntegers(const QString& command, const QStringList& args, const QList<Axis>& axes,
                          AxisVector* out)
{
    return named(command,
                 parseAxisAssignments<qint64>(args, axes, out, [](QStringView s, qint64* v) {
                     return numbers::parseInteger(s, v);
                 }));
}

Outcome parseAxisDoubles(const QString& command, const QStringList& args, const QList<Axis>& axes,
                         AxisVelocities* out)
{
    return named(command,
                 parseAxisAssignments<double>(args, axes, out, [](QStringView s, double* v) {
                     return numbers::parseReal(s, v);
                 }));
}

bool parseAxisMap(const QString& text, QMap<Axis, int>* out, QString* error)
{
    QMap<Axis, qint64> parsed;
    const Outcome read = parseAxisAssignments<qint64>(
        text.split(QLatin1Char(','), Qt::SkipEmptyParts), allAxes(), &parsed,
        [](QStringView s, qint64* v) { return numbers::parseInteger(s, 0, 255, v); });
    if (!read.ok()) {
        *error = tr("--axes: %1 (addresses 0..255)").arg(read.message);
        return false;
    }
    QMap<Axis, int> result;
    for (auto it = parsed.cbegin(); it != parsed.cend(); ++it)
        result.insert(it.key(), int(it.value()));
    *out = result;
    return true;
}

QString usageText()
{
    return tr("Usage: stepdeck-cli [--model MODEL] [--port PORT] [--address N] [--axes "
              "X=1,Y=2,Z=3] [--json] COMMAND [ARGS]\n"
              "\n"
              "Options (before or after the command):\n"
              "  --model MODEL      controller model (default: elab; see `models`)\n"
              "  --port PORT        serial device path | tcp://HOST:PORT | sim (in-process\n"
              "                     simulator; the default)\n"
              "  --address N        bus address of one drive (it becomes axis X)\n"
              "  --axes MAP         axis to bus address map for multi-drive links, e.g.\n"
              "                     X=1,Y=2,Z=3 (nanotec default); only these axes exist\n"
              "  --json             machine-readable output: one JSON line on stdout (an\n"
              "                     object; an array for scan and records)\n"
              "  --setup-defaults   write every parameter's schema default before the command\n"
              "                     (also the switch polarities; see `params`)\n"
              "  --timeout MS       how long to wait for the link to come up (default 3000)\n"
              "  --reset-line L     rts (default) or dtr: the modem line wired to the\n"
              "                     board's reset input (E-LAB `reset`); both are held low\n"
              "  --arrival-timeout MS  how long move and home wait for the axes to report\n"
              "                     arrival (laser-axis; default 60000, the laser's own)\n"
              "  --verbose          show the core's log output on stderr\n"
              "  --help, --version\n"
              "\n"
              "Commands:\n"
              "  ports                       serial ports with description and USB VID:PID\n"
              "                              (pseudo-terminals are not listed)\n"
              "  status                      one poll: machine and axis flags, positions,\n"
              "                              temperature\n"
              "  set NAME=V[,V,V] ...        write parameters; per-axis values in X,Y,Z(,U)\n"
              "                              order, or one value for every axis; models that\n"
              "                              can read them back verify every value (exit 11\n"
              "                              if a drive kept another one; --no-verify)\n"
              "  get NAME ...                read back where the protocol can, else say it\n"
              "                              cannot (exit 8)\n"
              "  export FILE                 parameter set as JSON: values read back where the\n"
              "                              model can, otherwise the schema defaults (E-LAB\n"
              "                              parameters are write-only); \"origin\" in the file\n"
              "                              says which is which\n"
              "  import FILE                 validates the whole file first, refuses it with\n"
              "                              one reason if anything is wrong, then writes\n"
              "                              every parameter in it (verified like set;\n"
              "                              --no-verify)\n"
              "  move [--abs] X=N Y=N Z=N    positioning move in steps; waits until idle and\n"
              "                              prints the positions (--no-wait: return at once;\n"
              "                              --timeout MS: stop it and exit 5 past MS)\n"
              "  jog X=V Y=V Z=V --for MS    jog at V steps/s for MS ms, ramped up and back\n"
              "                              to zero\n"
              "  home X=-1 Y=0 Z=1           reference move with a direction per axis; waits\n"
              "                              until idle and prints the positions (--no-wait;\n"
              "                              --timeout MS: stop it and exit 5 past MS; emis:\n"
              "                              X=1 selects an axis, --simultaneous runs them\n"
              "                              together)\n"
              "  velocity X=V Y=V Z=V        velocity move in steps/s; runs until Ctrl-C,\n"
              "                              SIGTERM or SIGHUP (or --for MS), then a ramped\n"
              "                              stop\n"
              "  feed X=N Y=N Z=N            feed move; waits until idle (--no-wait: one axis\n"
              "                              only; a multi-axis feed is streamed by the host)\n"
              "  stop | panic | reset        ramped stop | emergency stop | hardware reset\n"
              "  spindle RPM | coolant on|off | power PERCENT\n"
              "                              spindle speed, coolant, drive power in percent\n"
              "                              (checked against the parameter ranges)\n"
              "  scan [--first N] [--last N]\n"
              "                              drives answering on the bus (addresses 1..254):\n"
              "                              address and firmware string (multi-drive models\n"
              "                              such as nanotec; others exit 8)\n"
              "  records [AXIS]              the 32 stored records of one drive (nanotec)\n"
              "  store NAME=V[,V,V,V] ...    write power-on values (emis system parameters,\n"
              "                              ##...); store --clear sends *PESYS; `get` then\n"
              "                              reads the stored values back (*PRSYS)\n"
              "  output N on|off             switch a digital output (emis: 1..7)\n"
              "  program N --title TEXT CMD...  store the input program of input N (emis;\n"
              "                              inputs 1-4 carry the reference switches: --force);\n"
              "                              program N --erase deletes it\n"
              "  laser-bridge LASER_PORT [--map 1=X,2=Y,3=Z] [--scale STEPS_PER_UNIT]\n"
              "               [--home X=-1,Y=-1,Z=-1] [--door-input N]\n"
              "                              be the motor axes of a laser marker: answer its\n"
              "                              frames on LASER_PORT (9600 8N1) with this\n"
              "                              controller; runs until SIGINT/SIGTERM/SIGHUP,\n"
              "                              stops the motion it started and exits 0\n"
              "  models                      controller models known to this build\n"
              "  params                      the model's parameters: range, unit, default\n"
              "\n"
              "Positions are tracked by the host on models without position read-back\n"
              "(E-LAB): every invocation is a new session and starts with positions unknown\n"
              "(counted from 0), so `move --abs` is refused there; `move`, `home` and `feed`\n"
              "print the positions they end at.\n"
              "\n") +
           exitCodeHelp();
}

} // namespace stepdeck::cli
