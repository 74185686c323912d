// The command line of stepdeck-cli, parsed with QCommandLineParser (docs/cli.md): the global
// options up to the command name, then the rest with the global options plus the command's own.
#include "CliArguments.h"
#include "CliOutput.h"
#include "CliText.h"
#include "model/NearestName.h"
#include "model/NumberParsing.h"
#include "protocols/Registry.h"
#include <QCommandLineParser>
#include <QCoreApplication>
#include <limits>

namespace stepdeck::cli {

namespace {
// The global options: the parser's table and the "Options" part of --help. names: the short
// name (if any) first, the long name last; help: lines of the description.
struct GlobalOption
{
    const char* names;
    const char* valueName;
    const char* help;
};

// clang-format off
const GlobalOption kGlobalOptions[] = {
    {"machine", "FILE", QT_TRANSLATE_NOOP("stepdeck::cli::CliText",
        "a machine description (docs/machines.md) in place of\n--model/--port: axes by their "
        "names, values in their units")},
    {"controller", "ID", QT_TRANSLATE_NOOP("stepdeck::cli::CliText",
        "with --machine: the controller a per-controller command\n(set, get, scan, ...) talks "
        "to; required with several")},
    {"model", "MODEL", QT_TRANSLATE_NOOP("stepdeck::cli::CliText",
        "controller model (default: %1; see `models`)")},
    {"port", "PORT", QT_TRANSLATE_NOOP("stepdeck::cli::CliText",
        "serial device path | tcp://HOST:PORT | sim (in-process\nsimulator; the default)")},
    {"address", "N", QT_TRANSLATE_NOOP("stepdeck::cli::CliText",
        "bus address of one drive (it becomes axis X)")},
    {"axes", "MAP", QT_TRANSLATE_NOOP("stepdeck::cli::CliText",
        "axis to bus address map for multi-drive links, e.g.\nX=1,Y=2,Z=3 (nanotec default); "
        "only these axes exist")},
    {"json", nullptr, QT_TRANSLATE_NOOP("stepdeck::cli::CliText",
        "machine-readable output: one JSON line on stdout (an\nobject; an array for scan and "
        "records)")},
    {"setup-defaults", nullptr, QT_TRANSLATE_NOOP("stepdeck::cli::CliText",
        "write every parameter's schema default before the command\n(also the switch "
        "polarities; see `params`)")},
    {"timeout", "MS", QT_TRANSLATE_NOOP("stepdeck::cli::CliText",
        "how long to wait for the link to come up (default 3000;\nafter move, home and feed: "
        "their own --timeout)")},
    {"reset-line", "L", QT_TRANSLATE_NOOP("stepdeck::cli::CliText",
        "rts (default) or dtr: the modem line wired to the\nboard's reset input (E-LAB `reset`); "
        "both are held low")},
    {"arrival-timeout", "MS", QT_TRANSLATE_NOOP("stepdeck::cli::CliText",
        "how long move and home wait for the axes to report\narrival (laser-axis; default "
        "60000, the laser's own)")},
    {"v,verbose", nullptr, QT_TRANSLATE_NOOP("stepdeck::cli::CliText",
        "show the core's log output on stderr")},
    {"h,help", nullptr, QT_TRANSLATE_NOOP("stepdeck::cli::CliText", "show this help and exit")},
    {"version", nullptr, QT_TRANSLATE_NOOP("stepdeck::cli::CliText", "show the version and exit")},
};
// clang-format on

QStringList namesOf(const GlobalOption& option)
{
    return QString::fromLatin1(option.names).split(QLatin1Char(','));
}

const GlobalOption* findGlobal(const QString& name)
{
    for (const GlobalOption& option : kGlobalOptions) {
        if (namesOf(option).contains(name))
            return &option;
    }
    return nullptr;
}

// Every global option except those named in `shadowed` (the command's own of the same name).
void addGlobalOptions(QCommandLineParser* parser, const QStringList& shadowed = {})
{
    for (const GlobalOption& global : kGlobalOptions) {
        QCommandLineOption option(namesOf(global));
        if (global.valueName)
            option.setValueName(QString::fromLatin1(global.valueName));
        if (!shadowed.contains(option.names().constLast()))
            parser->addOption(option);
    }
}

QString optionsHelp()
{
    constexpr int kColumn = 21; // where the descriptions start, as in the Commands part
    QString text = CliText::tr("Options (before or after the command):\n");
    for (const GlobalOption& option : kGlobalOptions) {
        QStringList names;
        for (const QString& name : namesOf(option))
            names << (name.size() == 1 ? QStringLiteral("-") : QStringLiteral("--")) + name;
        QString left = QStringLiteral("  ") + names.join(QStringLiteral(", "));
        if (option.valueName)
            left += QLatin1Char(' ') + QLatin1String(option.valueName);
        left = left.size() < kColumn ? left.leftJustified(kColumn) : left + QStringLiteral("  ");
        const QString indent = QStringLiteral("\n") + QString(kColumn, QLatin1Char(' '));
        QString help = CliText::tr(option.help);
        if (namesOf(option).contains(QLatin1String("model")))
            help = help.arg(models().first().id); // the registry's first model is the default
        text += left + help.split(QLatin1Char('\n')).join(indent) + QLatin1Char('\n');
    }
    return text + QLatin1Char('\n');
}

// QCommandLineParser reads "-1" as the short option "1", but a negative number is a value, as
// it always was (`output -1 on` is a number out of range, exit 7, not an unknown option). Such
// an argument is hidden from the parser behind a NUL, which no real argument contains, and
// restored afterwards.
const QChar kNumberMark(0);

QStringList hideNegativeNumbers(QStringList arguments)
{
    for (QString& arg : arguments) {
        if (arg.size() > 1 && arg.at(0) == QLatin1Char('-') &&
            (arg.at(1).isDigit() || arg.at(1) == QLatin1Char('.')))
            arg.prepend(kNumberMark);
    }
    return arguments;
}

QString restored(QString arg)
{
    if (arg.startsWith(kNumberMark))
        arg.remove(0, 1);
    return arg;
}

QStringList restored(QStringList arguments)
{
    for (QString& arg : arguments)
        arg = restored(arg);
    return arguments;
}

// The long names of the global options and of `command`'s own: what an unknown option may
// have meant.
QStringList knownOptionNames(const CommandSyntax* command)
{
    QStringList names;
    for (const GlobalOption& option : kGlobalOptions)
        names << namesOf(option).constLast();
    if (command) {
        for (const CommandOption& option : command->options)
            names << QString::fromLatin1(option.name);
    }
    return names;
}

// One line for a parse failure: unknown options by name (with the nearest known one, if
// any), Qt's own text for the rest ("Missing value after '--for'.").
QString parseError(const QCommandLineParser& parser, const CommandSyntax* command)
{
    const QStringList unknown = parser.unknownOptionNames();
    if (!unknown.isEmpty()) {
        const QString& name = unknown.constFirst();
        const QString dashes = name.size() == 1 ? QStringLiteral("-") : QStringLiteral("--");
        const QString close =
            name.size() > 1 ? names::nearest(name, knownOptionNames(command)) : QString();
        if (!close.isEmpty())
            return CliText::tr("unknown option '%1' (did you mean --%2?)")
                .arg(dashes + name, close);
        return CliText::tr("unknown option '%1' (try --help)").arg(dashes + name);
    }
    QString text = parser.errorText();
    if (text.endsWith(QLatin1Char('.')))
        text.chop(1);
    if (!text.isEmpty())
        text[0] = text.at(0).toLower();
    return CliText::tr("%1 (try --help)").arg(text);
}

// A positive number of milliseconds (--timeout, --arrival-timeout).
bool parseMilliseconds(const QString& name, const QString& value, int* out, QString* error)
{
    if (numbers::parseInt(value, 1, std::numeric_limits<int>::max(), out) == NumberError::None)
        return true;
    *error = CliText::tr("--%1 needs a positive number of milliseconds").arg(name);
    return false;
}

// A global option with a value, by its long name. False with *error set on a bad value.
bool applyValue(const QString& name, const QString& value, CliOptions* o, QString* error)
{
    if (name == QLatin1String("model")) {
        o->model = value;
        o->modelOrPortGiven = true;
    } else if (name == QLatin1String("port")) {
        o->port = value;
        o->modelOrPortGiven = true;
    } else if (name == QLatin1String("machine")) {
        o->machineFile = value;
    } else if (name == QLatin1String("controller")) {
        o->controller = value;
    } else if (name == QLatin1String("axes")) {
        return parseAxisMap(value, &o->axisAddresses, &o->axisNames, error);
    } else if (name == QLatin1String("reset-line")) {
        const std::optional<LineSettings::ResetLine> line = resetLineFromName(value);
        if (!line) {
            *error = CliText::tr("--reset-line needs rts or dtr, got '%1'").arg(value);
            return false;
        }
        o->resetLine = *line;
    } else if (name == QLatin1String("address")) {
        int n = 0;
        if (numbers::parseInt(value, 0, std::numeric_limits<int>::max(), &n) != NumberError::None) {
            *error = CliText::tr("--address needs a non-negative number, got '%1'").arg(value);
            return false;
        }
        o->address = n;
    } else if (name == QLatin1String("arrival-timeout")) {
        return parseMilliseconds(name, value, &o->arrivalTimeoutMs, error);
    } else {
        return parseMilliseconds(name, value, &o->connectTimeoutMs, error);
    }
    return true;
}

// A global option without a value, by its long name.
void applyFlag(const QString& name, CliOptions* o)
{
    if (name == QLatin1String("json"))
        o->json = true;
    else if (name == QLatin1String("setup-defaults"))
        o->setupDefaults = true;
    else if (name == QLatin1String("verbose"))
        o->verbose = true;
    else if (name == QLatin1String("help"))
        o->help = true;
    else
        o->version = true;
}

// The options `parser` found: the command's own into o->commandOptions, the global ones into
// their fields (a later occurrence wins).
bool applyOptions(const QCommandLineParser& parser, const CommandSyntax* command, CliOptions* o,
                  QString* error)
{
    for (const QString& name : parser.optionNames()) {
        if (command) {
            for (const CommandOption& own : command->options) {
                if (name == QLatin1String(own.name))
                    o->commandOptions.insert(name, own.valueName ? restored(parser.value(name))
                                                                 : QString());
            }
            if (o->commandOptions.contains(name))
                continue;
        }
        const GlobalOption* global = findGlobal(name);
        const QString longName = namesOf(*global).constLast();
        if (global->valueName) {
            if (!applyValue(longName, restored(parser.value(name)), o, error))
                return false;
        } else {
            applyFlag(longName, o);
        }
    }
    return true;
}

const CommandSyntax* findCommand(const QList<CommandSyntax>& commands, const QString& name)
{
    for (const CommandSyntax& command : commands) {
        if (name == QLatin1String(command.name))
            return &command;
    }
    return nullptr;
}

// The arguments after the command name, with the global options plus the command's own.
bool parseCommandPart(const QString& program, const QStringList& rest, const CommandSyntax& command,
                      CliOptions* o, QString* error)
{
    QCommandLineParser parser;
    QStringList own;
    for (const CommandOption& option : command.options) {
        QCommandLineOption parserOption(QString::fromLatin1(option.name));
        if (option.valueName)
            parserOption.setValueName(QString::fromLatin1(option.valueName));
        parser.addOption(parserOption);
        own << parserOption.names();
    }
    addGlobalOptions(&parser, own);
    if (!parser.parse(QStringList{program} + rest)) {
        *error = parseError(parser, &command);
        return false;
    }
    o->args = restored(parser.positionalArguments());
    return applyOptions(parser, &command, o, error);
}
} // namespace

std::optional<QString> CliOptions::value(const char* name) const
{
    const auto it = commandOptions.constFind(QLatin1String(name));
    return it == commandOptions.cend() ? std::nullopt : std::optional<QString>(*it);
}

bool parseArguments(const QStringList& arguments, const QList<CommandSyntax>& commands,
                    CliOptions* options, QString* error)
{
    CliOptions o;
    o.model = models().first().id;
    QCommandLineParser global; // up to the command name; the rest stays positional
    global.setOptionsAfterPositionalArgumentsMode(QCommandLineParser::ParseAsPositionalArguments);
    addGlobalOptions(&global);
    if (!global.parse(hideNegativeNumbers(arguments))) {
        *error = parseError(global, nullptr);
        return false;
    }
    if (!applyOptions(global, nullptr, &o, error))
        return false;
    const QStringList positional = global.positionalArguments();
    if (!positional.isEmpty()) {
        o.command = restored(positional.constFirst());
        const CommandSyntax* command = findCommand(commands, o.command);
        if (!command) {
            *error = unknownCommandText(o.command, commands);
            return false;
        }
        if (!parseCommandPart(arguments.value(0), positional.mid(1), *command, &o, error))
            return false;
    }
    if (o.address && !o.axisAddresses.isEmpty()) {
        *error = CliText::tr("give either --address or --axes, not both");
        return false;
    }
    if (!o.machineFile.isEmpty() &&
        (o.modelOrPortGiven || o.address || !o.axisAddresses.isEmpty())) {
        *error = CliText::tr("give either --machine or --model/--port/--address/--axes, not both "
                             "(the machine file names its controllers)");
        return false;
    }
    if (!o.controller.isEmpty() && o.machineFile.isEmpty()) {
        *error = CliText::tr("--controller needs --machine FILE");
        return false;
    }
    if (o.command.isEmpty() && !o.help && !o.version) {
        *error = CliText::tr("no command given (try --help)");
        return false;
    }
    *options = o;
    return true;
}

QString unknownCommandText(const QString& name, const QList<CommandSyntax>& commands)
{
    QStringList known;
    for (const CommandSyntax& command : commands)
        known << QString::fromLatin1(command.name);
    const QString close = names::nearest(name, known);
    return close.isEmpty()
               ? CliText::tr("unknown command '%1' (try --help)").arg(name)
               : CliText::tr("unknown command '%1' (did you mean %2?)").arg(name, close);
}

namespace {
// "1..254": the bus addresses of the multi-drive models this build knows (their Capabilities).
QString busAddressRange()
{
    int first = 0;
    int last = -1;
    for (const ModelInfo& model : models()) {
        const Capabilities& c = model.capabilities;
        if (!c.multiDrive)
            continue;
        first = last < first ? c.minBusAddress : qMin(first, c.minBusAddress);
        last = qMax(last, c.maxBusAddress);
    }
    return last < first ? QStringLiteral("-") : QStringLiteral("%1..%2").arg(first).arg(last);
}
} // namespace

namespace {
QString machineHelp()
{
    return CliText::tr(
        "With --machine FILE (a machine description, docs/machines.md) the axes are the\n"
        "machine's, by name, in their units:\n"
        "  move [--abs] X=12.5 A=90    positioning in mm, deg or steps; checked as a whole,\n"
        "                              nothing is sent if any part is refused\n"
        "  jog X=5 A=-10 --for MS      jog in unit/s, every controller on one input\n"
        "  home [AXIS ...]             reference runs in the file's order and directions\n"
        "  stop | panic                every controller at once\n"
        "  status                      every axis in its unit, every controller's link\n"
        "  machine                     the resolved controllers and axes\n"
        "Every other command talks to one controller: --controller ID (required when\n"
        "the machine has several).\n"
        "\n");
}
// Motion programs (issue 20): a paragraph of its own, so the machine part keeps its text.
QString programHelp()
{
    return CliText::tr(
        "Motion programs (docs/programs.md), on a machine file or --model/--port:\n"
        "  run PROGRAM [--dry-run] [--from-line N] [--skip-pauses]\n"
        "      [--optional-stops on|off] [--feed-override PERCENT]\n"
        "                              checks the whole program first (exit 7 with every\n"
        "                              FILE:LINE:COL error, nothing sent), then runs it\n"
        "                              block by block: a line per block on stderr (--json:\n"
        "                              an event per block on stdout); exit 3/4/5/6 at the\n"
        "                              failing line, 130 on Ctrl-C; M0 waits for Enter\n"
        "                              (without a terminal: exit 2 unless --skip-pauses);\n"
        "                              M1 too while --optional-stops is on (the default)\n"
        "      [--block-delete on|off] lines starting with \"/\" are skipped while on (the\n"
        "                              default, as LinuxCNC), run while off\n"
        "                              --dry-run prints lines, extents and the estimated\n"
        "                              duration and moves nothing\n"
        "      [--dry-run --canon]     the program's motion commands instead, one per line\n"
        "                              as LinuxCNC's rs274 prints them (docs/cli.md)\n"
        "                              --feed-override 10..200: contours at that share of F;\n"
        "                              Ctrl-Z holds the feed, SIGCONT (fg) resumes it\n"
        "      [--tool-table FILE] [--offsets G54:X=N,Y=N;G55:...]\n"
        "                              the tool table (LinuxCNC tool.tbl) G43 and M6 use,\n"
        "                              and the work zeros of G54..G59 (G54 active); without\n"
        "                              --offsets a machine file's zeros as the window keeps\n"
        "                              them (said on stderr)\n"
        "      [--reference]           references every axis first (the file's order and\n"
        "                              directions), as home without axes\n"
        "\n");
}
} // namespace

QString usageText()
{
    return CliText::tr("Usage: stepdeck-cli [--model MODEL] [--port PORT] [--address N] [--axes "
                       "X=1,Y=2,Z=3] [--json] COMMAND [ARGS]\n"
                       "\n") +
           optionsHelp() +
           CliText::tr(
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
               "                              drives answering on the bus (addresses %1):\n"
               "                              address and firmware string (multi-drive models\n"
               "                              such as nanotec; others exit 8)\n"
               "  records [AXIS]              the 32 stored records of one drive (nanotec)\n"
               "  closed-loop [AXIS] [on|off|reset-error]\n"
               "                              closed loop of an encoder drive (nanotec, manual\n"
               "                              8.1): motor data and encoder check; on/off switches\n"
               "                              it and reads it back (exit 11 when the drive\n"
               "                              ignored it); reset-error clears a position error\n"
               "  calibrate [AXIS]            calibration run (!101) for a newly connected motor:\n"
               "                              THE MOTOR TURNS; progress every second, then the\n"
               "                              result (exit 4 when the drive reports a failure)\n"
               "  home --closed-loop X=1      the closed-loop reference run (!8), needed after\n"
               "                              every power-on before closed loop can be on\n"
               "  reset-position-error [AXIS] clear a drive's position error; its position\n"
               "                              becomes the encoder's (nanotec 'D')\n"
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
               "  machine check FILE          validate a machine description (docs/machines.md)\n"
               "                              and print its controllers and axes (exit 7 names\n"
               "                              the first wrong field)\n"
               "  params                      the model's parameters: range, unit, default\n"
               "\n"
               "Positions are tracked by the host on models without position read-back\n"
               "(E-LAB): every invocation is a new session and starts with positions unknown\n"
               "(counted from 0), so `move --abs` is refused there; `move`, `home` and `feed`\n"
               "print the positions they end at.\n"
               "\n"
               "Arguments that start with '-' are options: an unknown option or one of another\n"
               "command is a usage error (exit 2). Everything after `--` is an argument.\n"
               "\n")
               .arg(busAddressRange()) +
           machineHelp() + programHelp() + exitCodeHelp();
}

} // namespace stepdeck::cli
