// The SMC-IC4 as a model: line settings, capabilities, presentation and its registry entry
// (core/protocols/Registry.cpp).
#include "EmisModel.h"
#include "EmisCodec.h"
#include "EmisController.h"
#include "EmisGrammar.h"
#include "EmisLogging.h"
#include "EmisParameterPlan.h"
#include "EmisSimulator.h"

namespace stepdeck::emis {

LineSettings lineSettings()
{
    LineSettings line;
    line.baudRate = 115200;
    line.dataBits = 8;
    line.stopBits = 1;
    line.parity = LineSettings::Parity::None;
    return line;
}

Capabilities capabilities()
{
    Capabilities caps;
    caps.axes = emisAxes(); // the codec's table (issue 32)
    // Jog is a chain of short vector moves (EmisController); no feed and no velocity move:
    // without a stop command nothing may run that does not end by itself.
    caps.motionModes = {MotionMode::Jog, MotionMode::RelativeMove, MotionMode::AbsoluteMove,
                        MotionMode::Reference};
    caps.positionReadback = false; // chapter 9 has no position query
    caps.rampedStop = false;
    caps.stopCommand = false; // chapter 9 documents no stop command at all
    caps.panic = false;
    caps.hostRampedJog = false; // every chunk is a vector move with the board's own ramp (9.6)
    caps.maxJogSpeed = 10000;   // steps/s; the work speed a jog chunk runs at
    caps.defaultJogAcceleration = 1e7; // the host ramp passes the targets through
    caps.digitalInputs = kInputCount;
    caps.digitalOutputs = kOutputCount;
    caps.storedParameters = true;
    caps.inputPrograms = true;
    caps.referenceDirection = false; // "$Hx" has no direction (9.9)
    // G1 F: the work speed #E1 (9.5) every vector move runs at, G0 too.
    caps.feedRateParameter = "work-speed";
    caps.feedRateSetsRapid = true;
    // A G1 over several axes: each axis' work speed its share of F, with interpolation on
    // (IP1, 9.12), so the board brings them into their targets together.
    caps.coordinatedFeed = true;
    caps.interpolationParameter = "interpolation";
    return caps;
}

namespace {
ParameterSpec spec(const char* name, const char* label, const char* group, const char* unit,
                   qint64 minimum, qint64 maximum, bool perAxis, QVariant def, const char* desc)
{
    ParameterSpec s;
    s.name = QString::fromUtf8(name);
    s.label = QString::fromUtf8(label);
    s.group = QString::fromUtf8(group);
    s.unit = QString::fromUtf8(unit);
    s.type = ParameterType::Integer;
    s.minimum = minimum;
    s.maximum = maximum;
    s.perAxis = perAxis;
    s.readable = false; // no command reads a working value back; `get` reports *PRSYS
    s.defaultValue = std::move(def);
    s.description = QString::fromUtf8(desc);
    return s;
}
} // namespace

ParameterSchema parameterSchema()
{
    using namespace limits;
    QList<ParameterSpec> specs;
    specs << spec(
        "start-speed", QT_TRANSLATE_NOOP("Parameters", "Start speed"),
        QT_TRANSLATE_NOOP("Parameters", "Speeds"), QT_TRANSLATE_NOOP("Parameters", "steps/s"),
        kSpeedMin, kSpeedMax, true, 200,
        QT_TRANSLATE_NOOP("Parameters",
                          "Speed at which every move starts and ends its ramp (#S, 9.4)"));
    specs << spec(
        "work-speed", QT_TRANSLATE_NOOP("Parameters", "Work speed"),
        QT_TRANSLATE_NOOP("Parameters", "Speeds"), QT_TRANSLATE_NOOP("Parameters", "steps/s"),
        kSpeedMin, kSpeedMax, true, 1000,
        QT_TRANSLATE_NOOP("Parameters", "Speed of vector moves after the ramp (#E1, 9.5)"));
    specs << spec(
        "ramp", QT_TRANSLATE_NOOP("Parameters", "Ramp"), QT_TRANSLATE_NOOP("Parameters", "Speeds"),
        QT_TRANSLATE_NOOP("Parameters", "ms"), kRampMin, kRampMax, false, 100,
        QT_TRANSLATE_NOOP("Parameters",
                          "Time from start speed to work speed and back, all motors (#R, 9.6)"));
    specs << spec(
        "reference-speed", QT_TRANSLATE_NOOP("Parameters", "Reference speed"),
        QT_TRANSLATE_NOOP("Parameters", "Referencing"), QT_TRANSLATE_NOOP("Parameters", "steps/s"),
        kSpeedMin, kSpeedMax, false, 400,
        QT_TRANSLATE_NOOP("Parameters",
                          "Speed of reference runs, one value for all motors (#E9, 9.5)"));
    specs << spec("reference-offset", QT_TRANSLATE_NOOP("Parameters", "Offset after referencing"),
                  QT_TRANSLATE_NOOP("Parameters", "Referencing"),
                  QT_TRANSLATE_NOOP("Parameters", "steps"), 0, kOffsetMax, true, 10,
                  QT_TRANSLATE_NOOP(
                      "Parameters",
                      "Steps the motor moves out of its switch after a reference run (#O, 9.10); "
                      "not a system parameter"));
    ParameterSpec switchType = spec(
        "reference-switch-type", QT_TRANSLATE_NOOP("Parameters", "Reference switch type"),
        QT_TRANSLATE_NOOP("Parameters", "Referencing"), "", 0, 0, true, QStringLiteral("NO"),
        QT_TRANSLATE_NOOP("Parameters", "NO: normally open (Schließer, the default), NC: normally "
                                        "closed (Öffner); inputs 1-4 (##REFSW, 9.14, 5.2.1)"));
    switchType.type = ParameterType::Choice;
    switchType.choices = {QString::fromUtf8(QT_TRANSLATE_NOOP("Parameters", "NO")),
                          QString::fromUtf8(QT_TRANSLATE_NOOP("Parameters", "NC"))};
    switchType.warning = QStringLiteral(QT_TRANSLATE_NOOP(
        "Parameters",
        "The type must match the wired switches, or reference runs end in the wrong place. It "
        "is stored in the board's system parameters and kept after power-off."));
    specs << switchType;

    ParameterSpec resolution =
        spec("step-resolution", QT_TRANSLATE_NOOP("Parameters", "Step resolution"),
             QT_TRANSLATE_NOOP("Parameters", "Drive"),
             QT_TRANSLATE_NOOP("Parameters", "microsteps"), 0, 0, true, QStringLiteral("16"),
             QT_TRANSLATE_NOOP("Parameters", "Microsteps per full step (D, 9.7)"));
    resolution.type = ParameterType::Choice;
    for (int v = 1; v <= 256; v *= 2)
        resolution.choices << QString::number(v);
    resolution.warning = QStringLiteral(QT_TRANSLATE_NOOP(
        "Parameters",
        "Changes the length of a step: every position, distance and speed in steps changes its "
        "meaning."));
    specs << resolution;
    ParameterSpec run =
        spec("run-current", QT_TRANSLATE_NOOP("Parameters", "Run current"),
             QT_TRANSLATE_NOOP("Parameters", "Drive"), QT_TRANSLATE_NOOP("Parameters", "%"), 0,
             kRunCurrentMax, true, 100,
             QT_TRANSLATE_NOOP("Parameters",
                               "Motor current while moving, % of the driver's rating (c, 9.8)"));
    run.warning = QString::fromUtf8(QT_TRANSLATE_NOOP(
        "Parameters", "A current above the motor's rating overheats motor and driver stage."));
    specs << run;
    specs << spec(
        "idle-current", QT_TRANSLATE_NOOP("Parameters", "Idle current"),
        QT_TRANSLATE_NOOP("Parameters", "Drive"), QT_TRANSLATE_NOOP("Parameters", "%"), 0,
        kIdleCurrentMax, true, 20,
        QT_TRANSLATE_NOOP(
            "Parameters",
            "Motor current at standstill, % of the driver's rating (c, 9.8); 0 leaves the "
            "motor without holding torque"));
    ParameterSpec interpolation = spec(
        "interpolation", QT_TRANSLATE_NOOP("Parameters", "Interpolation"),
        QT_TRANSLATE_NOOP("Parameters", "Drive"), "", 0, 0, false, true,
        QT_TRANSLATE_NOOP("Parameters", "On: the axes of a vector move arrive together; off: each "
                                        "axis moves at its own speed (IP, 9.12)"));
    interpolation.type = ParameterType::Boolean;
    specs << interpolation;
    return ParameterSchema(specs);
}

// ---- presentation ----

namespace {

const char* controlName(char c)
{
    switch (c) {
    case kCr:
        return "<CR>";
    case kStx:
        return "<STX>";
    case kEtx:
        return "<ETX>";
    case kAck:
        return "<ACK>";
    case kBel:
        return "<BEL>";
    case kNak:
        return "<NAK>";
    case 0x11:
        return "<DC1>";
    case 0x12:
        return "<DC2>";
    case 0x13:
        return "<DC3>";
    case 0x14:
        return "<DC4>";
    case '\n':
        return "<LF>";
    default:
        return nullptr;
    }
}
} // namespace

QString formatTraffic(const QByteArray& bytes)
{
    QString out;
    for (char c : bytes) {
        const auto b = static_cast<unsigned char>(c);
        if (const char* name = controlName(c))
            out += QLatin1String(name);
        else if (b >= 0x20 && b < 0x7F && c != '<')
            out += QLatin1Char(c);
        else
            out += QStringLiteral("<x%1>").arg(
                QString::number(b, 16).toUpper().rightJustified(2, QLatin1Char('0')));
    }
    return out;
}

bool parseTraffic(const QString& text, QByteArray* bytes, QString* error)
{
    QByteArray out;
    for (int i = 0; i < text.size(); ++i) {
        const QChar ch = text.at(i);
        if (ch == QLatin1Char('<')) {
            const int end = text.indexOf(QLatin1Char('>'), i);
            const QString token = end > i ? text.mid(i, end - i + 1).toUpper() : QString();
            bool known = false;
            for (int b = 0; b < 0x20 && !known; ++b) {
                const char* name = controlName(char(b));
                if (name && token == QLatin1String(name)) {
                    out += char(b);
                    known = true;
                }
            }
            bool ok = false;
            if (!known && token.size() == 5 && token.startsWith(QLatin1String("<X"))) {
                out += char(token.mid(2, 2).toInt(&ok, 16));
                known = ok;
            }
            if (!known) {
                if (error)
                    *error = QCoreApplication::translate("stepdeck::emis::Presentation",
                                                         "unknown control name at column %1 "
                                                         "(known: <CR> <STX> <ETX> <xNN>)")
                                 .arg(i + 1);
                return false;
            }
            i = end;
        } else if (ch.unicode() >= 0x20 && ch.unicode() < 0x7F) {
            out += char(ch.unicode());
        } else {
            if (error)
                *error = QCoreApplication::translate("stepdeck::emis::Presentation",
                                                     "non-ASCII character at column %1")
                             .arg(i + 1);
            return false;
        }
    }
    if (!out.endsWith(kCr) && !out.endsWith(kStx) && !out.endsWith(kEtx))
        out += kCr;
    *bytes = out;
    return true;
}

QString noStopNote()
{
    return QCoreApplication::translate(
        "stepdeck::emis::Presentation",
        "no stop command: a button on the reset input (manual 5.8) or the machine's emergency "
        "stop stops it; positions are then unknown until referenced");
}

QString noStopNoteDetail()
{
    return QCoreApplication::translate(
        "stepdeck::emis::Presentation",
        "A move only ends when it arrives. A reset (a normally open button on the board's reset "
        "input) stops every motor at once and restarts the board with its stored values. "
        "StepDeck sees it when a move's arrival does not come (that axis: motion unconfirmed, "
        "position unknown) or when the board does not answer while it restarts; either way every "
        "axis then counts as not referenced and the outputs as unknown. A reset it could not see "
        "leaves the positions it shows: reference the axes after every reset.");
}

ModelPresentation presentation()
{
    ModelPresentation p;
    p.statusWords = [](const QList<Axis>&) {
        StatusWordInfo w;
        w.key = QStringLiteral("inputs");
        w.title = QCoreApplication::translate("stepdeck::emis::Presentation", "Inputs (@IG, 9.2)");
        w.width = 8;
        for (int i = 0; i < kInputCount; ++i) {
            StatusBitInfo bit;
            bit.bit = i;
            bit.name = QStringLiteral("IN%1").arg(i + 1);
            bit.description =
                i < 4 ? QCoreApplication::translate("stepdeck::emis::Presentation",
                                                    "Input %1: reference switch of axis %2 (or a "
                                                    "free input when no switch is wired).")
                            .arg(i + 1)
                            .arg(axisName(*axisOfNumber(i + 1)))
                      : QCoreApplication::translate("stepdeck::emis::Presentation",
                                                    "Input %1: free input.")
                            .arg(i + 1);
            w.bits << bit;
        }
        return QList<StatusWordInfo>{w};
    };
    p.formatTraffic = &formatTraffic;
    p.parseTraffic = &parseTraffic;
    p.trafficExample = [] {
        return QCoreApplication::translate(
            "stepdeck::emis::Presentation",
            "Send a command, e.g. @V (firmware version) or @IG (inputs); the final <CR> is added.");
    };
    p.checkProgramCommand = [](const QString& line) {
        for (QChar c : line) {
            if (c.unicode() < 0x20 || c.unicode() >= 0x7F)
                return QCoreApplication::translate("stepdeck::emis::Presentation",
                                                   "not printable ASCII");
        }
        return validateProgramLine(line.trimmed().toLatin1());
    };
    p.noStopNote = &noStopNote;
    p.noStopNoteDetail = &noStopNoteDetail;
    return p;
}

namespace {
// The registry's display name, shown through QCoreApplication::translate("Models", ...).
const char* const kDisplayName = QT_TRANSLATE_NOOP("Models", "EMIS SMC-IC4 4-axis controller");
} // namespace
Q_LOGGING_CATEGORY(lcEmis, "stepdeck.emis", QtWarningMsg)

ModelInfo modelInfo()
{
    ModelInfo info;
    info.id = QStringLiteral("emis");
    info.displayName = QString::fromLatin1(kDisplayName);
    info.line = lineSettings();
    info.capabilities = capabilities();
    info.schema = parameterSchema();
    // The adapter's own plan (run and idle current go together, 9.8), so the check and the
    // CLI's --setup-defaults refuse what the write would.
    info.parameterRules = [](const ParameterSchema&, const ParameterSet& set,
                             const ParameterSet& known) {
        CurrentPartners partners;
        auto take = [&known](const char* name, QMap<Axis, qint64>* out) {
            const ParameterValue v = known.value(QLatin1String(name));
            for (auto it = v.perAxis.cbegin(); it != v.perAxis.cend(); ++it)
                out->insert(it.key(), it.value().toLongLong());
        };
        take("run-current", &partners.runKnown);
        take("idle-current", &partners.idleKnown);
        const ParameterPlan plan = planWorking(set, partners);
        return plan.ok() ? QString() : plan.message;
    };
    info.scenario = scenarioSupport();
    info.soak = soakProfile();
    info.presentation = presentation();
    info.logging = &lcEmis;
    return describeModel<EmisController, EmisSimulator>(std::move(info));
}

} // namespace stepdeck::emis
