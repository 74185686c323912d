#include "ElabModel.h"
#include "ElabCodec.h"
#include "ElabController.h"
#include "ElabCtlParameters.h"
#include "ElabLogging.h"
#include "ElabSimulator.h"
#include <QCoreApplication>
#include <QtGlobal>

namespace stepdeck::elab {

Q_LOGGING_CATEGORY(lcElab, "stepdeck.elab", QtWarningMsg)

LineSettings lineSettings()
{
    LineSettings line;
    line.baudRate = 57600;
    line.dataBits = 8;
    line.stopBits = 2;
    line.parity = LineSettings::Parity::None;
    return line;
}

Capabilities capabilities()
{
    Capabilities caps;
    caps.axes = boardAxes(); // the codec's table (issue 32)
    caps.motionModes = {MotionMode::Jog,     MotionMode::RelativeMove, MotionMode::AbsoluteMove,
                        MotionMode::Feed,    MotionMode::FeedStream,   MotionMode::Reference,
                        MotionMode::Velocity};
    caps.spindle = true;
    caps.coolant = true;
    caps.drivePower = true;
    caps.temperature = true;
    caps.startButton = true;
    caps.positionReadback = false; // no documented reply carries absolute positions
    caps.rampedStop = true;        // ForceStopMove
    caps.panic = true;             // ForcePanicStop
    caps.resetLine = true;         // RTS -> external reset (jumper J7)
    caps.hostRampedJog = true;     // "Befehle im Jogbetrieb": the host ramps jog rates
    caps.maxJogSpeed = 5000;       // jog rates are signed 16-bit; this is the UI ceiling
    caps.defaultJogAcceleration = 2000;
    // G1 F: feed mode (SetFeedSpeed <FS>, a constant rate without ramp); G0 keeps max-speed.
    caps.feedRateParameter = "feed-speed";
    caps.feedRateUsesFeedMode = true;
    caps.feedRateWholeSet = true; // <FS> carries X, Y and Z in one frame
    caps.spindleSpeedParameter = "spindle-rpm";
    // A contour is one <DC2> stream (manual, "SetFeedStepXYZ": the board empties its step
    // buffer at the feed rate, one vector per tick). 57600 8N2 carries 5 236 characters/s,
    // 2 618 <DC2> pairs; at most 2 100 ticks/s, so that the status polls keep their share of
    // the wire while it streams (issue 47: at least 10 reads a second; the arithmetic is at
    // ElabCtlMotionOps::kContourMaxTickRate). The program check takes the same number
    // (motion::StreamExecutor::tickRate).
    caps.contourStream = true;
    caps.contourTickBelow = "start-speed";
    caps.contourMaxTickRate = ElabCtlMotionOps::kContourMaxTickRate;
    return caps;
}

ModelInfo modelInfo()
{
    ModelInfo info;
    info.id = QStringLiteral("elab");
    // Shown through QCoreApplication::translate("Models", ...).
    info.displayName =
        QString::fromUtf8(QT_TRANSLATE_NOOP("Models", "E-LAB 3-axis stepper controller"));
    info.line = lineSettings();
    info.capabilities = capabilities();
    info.schema = parameterSchema();
    // tmInvSetup until the ramp is written; feeds need their speed.
    info.setupBeforeMotion = {QStringLiteral("start-speed"), QStringLiteral("max-speed"),
                              QStringLiteral("acceleration"), QStringLiteral("feed-speed")};
    // The same rules the adapter applies when it writes (completion from the known values,
    // feed speed below start speed), so a program's check refuses what the run would.
    info.parameterRules = [](const ParameterSchema& schema, const ParameterSet& set,
                             const ParameterSet& known) {
        QList<ElabParameterWrite> unused;
        return ElabCtlParameters::plan(schema, set, known, &unused);
    };
    info.scenario = scenarioSupport();
    info.soak = soakProfile();
    info.streamBench = streamBenchProfile();
    info.presentation = presentation();
    info.logging = &lcElab;
    return describeModel<ElabController, ElabSimulator>(std::move(info));
}

// ---- presentation (status panel tooltips, traffic console) ----

namespace {
// Plain words for the status panel, after the manual's RequestMachineState and
// RequestAxeState tables. Marked for lupdate; translated when presentation() is called.
struct BitText
{
    int bit;
    const char* name;
    const char* text;
    bool implemented;
    bool fault;
};

constexpr const char* kContext = "stepdeck::elab::Presentation";

const BitText kMachineBits[] = {
    {0, "tmDriveOn", QT_TRANSLATE_NOOP("stepdeck::elab::Presentation", "The motors are powered."),
     true, false},
    {1, "tmSpindleOn",
     QT_TRANSLATE_NOOP("stepdeck::elab::Presentation", "The spindle motor is switched on."), true,
     false},
    {2, "tmBusy", QT_TRANSLATE_NOOP("stepdeck::elab::Presentation", "At least one axis is moving."),
     true, false},
    {3, "tmCOMfail",
     QT_TRANSLATE_NOOP("stepdeck::elab::Presentation",
                       "Serial port error (documented, but never set by the firmware)."),
     false, true},
    {4, "tmTimeOut",
     QT_TRANSLATE_NOOP("stepdeck::elab::Presentation",
                       "Internal error (documented, but never set by the firmware)."),
     false, true},
    {5, "tmParmError",
     QT_TRANSLATE_NOOP("stepdeck::elab::Presentation",
                       "Parameter error (documented, but never set by the firmware)."),
     false, true},
    {6, "tmOverTemp",
     QT_TRANSLATE_NOOP("stepdeck::elab::Presentation",
                       "The board temperature is above 50 °C; the drivers may switch off."),
     true, true},
    {7, "tmInvSetup",
     QT_TRANSLATE_NOOP("stepdeck::elab::Presentation",
                       "Setup incomplete: start speed, max speed and acceleration must all be "
                       "written before moving."),
     true, true},
    {8, "tmLimSwX",
     QT_TRANSLATE_NOOP("stepdeck::elab::Presentation", "A limit switch of the X axis is active."),
     true, true},
    {9, "tmLimSwY",
     QT_TRANSLATE_NOOP("stepdeck::elab::Presentation", "A limit switch of the Y axis is active."),
     true, true},
    {10, "tmLimSwZ",
     QT_TRANSLATE_NOOP("stepdeck::elab::Presentation", "A limit switch of the Z axis is active."),
     true, true},
    {11, "tmRefSwX",
     QT_TRANSLATE_NOOP("stepdeck::elab::Presentation",
                       "The reference switch of the X axis is active."),
     true, false},
    {12, "tmRefSwY",
     QT_TRANSLATE_NOOP("stepdeck::elab::Presentation",
                       "The reference switch of the Y axis is active."),
     true, false},
    {13, "tmRefSwZ",
     QT_TRANSLATE_NOOP("stepdeck::elab::Presentation",
                       "The reference switch of the Z axis is active."),
     true, false},
    {14, "tmPanicStop",
     QT_TRANSLATE_NOOP("stepdeck::elab::Presentation",
                       "Emergency stop: the board's panic switch is active or the host sent "
                       "ForcePanicStop."),
     true, true},
};

const BitText kAxeBits[] = {
    {0, "taXMove",
     QT_TRANSLATE_NOOP("stepdeck::elab::Presentation", "The X axis runs a move or feed."), true,
     false},
    {1, "taXJog", QT_TRANSLATE_NOOP("stepdeck::elab::Presentation", "The X axis is jogging."), true,
     false},
    {2, "taYMove",
     QT_TRANSLATE_NOOP("stepdeck::elab::Presentation", "The Y axis runs a move or feed."), true,
     false},
    {3, "taYJog", QT_TRANSLATE_NOOP("stepdeck::elab::Presentation", "The Y axis is jogging."), true,
     false},
    {4, "taZMove",
     QT_TRANSLATE_NOOP("stepdeck::elab::Presentation", "The Z axis runs a move or feed."), true,
     false},
    {5, "taZJog", QT_TRANSLATE_NOOP("stepdeck::elab::Presentation", "The Z axis is jogging."), true,
     false},
    {6, "taLimSw",
     QT_TRANSLATE_NOOP("stepdeck::elab::Presentation",
                       "A limit switch is active: only jog moves are accepted."),
     true, true},
    {7, "taRefSw",
     QT_TRANSLATE_NOOP("stepdeck::elab::Presentation", "A reference switch is active."), true,
     false},
};

template <size_t N> QList<StatusBitInfo> bitList(const BitText (&table)[N])
{
    QList<StatusBitInfo> bits;
    for (const BitText& t : table) {
        bits << StatusBitInfo{t.bit, QString::fromLatin1(t.name),
                              QCoreApplication::translate(kContext, t.text), t.implemented,
                              t.fault};
    }
    return bits;
}
} // namespace

ModelPresentation presentation()
{
    ModelPresentation p;
    p.statusWords = [](const QList<Axis>&) {
        // Keys as the adapter publishes them in MachineStatus::raw.
        StatusWordInfo machineWord{
            QStringLiteral("machineState"),
            QCoreApplication::translate("stepdeck::elab::Presentation",
                                        "Machine state (RequestMachineState)"),
            16, bitList(kMachineBits), std::nullopt};
        StatusWordInfo axeWord{QStringLiteral("axeState"),
                               QCoreApplication::translate("stepdeck::elab::Presentation",
                                                           "Axis state (RequestAxeState)"),
                               8, bitList(kAxeBits), std::nullopt};
        return QList<StatusWordInfo>{machineWord, axeWord};
    };
    p.formatTraffic = [](const QByteArray& bytes) { return toMnemonics(bytes); };
    p.trafficExample = [] {
        return QCoreApplication::translate("stepdeck::elab::Presentation",
                                           "Send raw bytes, e.g. <ENQ> or <DC4>0064,0000;0000.");
    };
    p.parseTraffic = [](const QString& text, QByteArray* bytes, QString* error) {
        return fromMnemonics(text, bytes, error);
    };
    return p;
}

} // namespace stepdeck::elab
