#include "NanotecModel.h"
#include "NanotecCodec.h"
#include "NanotecController.h"
#include "NanotecLogging.h"
#include "NanotecSchema.h"
#include "NanotecSimulator.h"

namespace stepdeck::nanotec {

Q_LOGGING_CATEGORY(lcNanotec, "stepdeck.nanotec", QtWarningMsg)

LineSettings lineSettings()
{
    LineSettings line;
    line.baudRate = 19200;
    line.dataBits = 8;
    line.stopBits = 1;
    line.parity = LineSettings::Parity::None;
    return line;
}

QMap<Axis, int> defaultAxisAddresses()
{
    return {{Axis::X, 1}, {Axis::Y, 2}, {Axis::Z, 3}};
}

Capabilities capabilities(const QList<Axis>& axes)
{
    Capabilities caps;
    caps.axes = axes;
    caps.motionModes = {MotionMode::Jog, MotionMode::RelativeMove, MotionMode::AbsoluteMove,
                        MotionMode::Reference, MotionMode::Velocity};
    caps.positionReadback = true; // 'C' (5.17)
    // A drive sent 'A' is "moving" until a '$' read after it shows ready (motionPending),
    // published before the move's request finishes (NanotecMotion::startPositioning).
    caps.statusHoldsStartedMove = true;
    // 'S' stops without a ramp (6.2); only speed-mode runs can be ramped down first.
    caps.rampedStop = false;
    caps.panic = true; // '#*S' to every drive at once
    caps.multiDrive = true;
    caps.minBusAddress = kMinAddress; // 1.1
    caps.maxBusAddress = kMaxAddress;
    caps.records = true; // "read-all-records", "write-record", ... (section 4, 5.15)
    // Calibration and closed-loop reference runs, closed loop on/off (8.1, NanotecClosedLoop).
    caps.closedLoop = true;
    // Speed mode ramps speed and direction changes itself (6.6, !2 p1): the host ramp only
    // passes the targets through.
    caps.hostRampedJog = false;
    caps.maxJogSpeed = 25000; // 'o' range (6.9)
    caps.defaultJogAcceleration = 1e7;
    // G1 F: the top speed o (6.9) of the positioning move, which G0 runs at too.
    caps.feedRateParameter = "max-frequency";
    caps.feedRateSetsRapid = true;
    // A G1 over several drives: each drive's o its share of F; set up first and started one
    // right after the other (NanotecMotion::startPositioning), they arrive together.
    caps.coordinatedFeed = true;
    caps.moveSetupSeconds = 0.06; // docs/benchmark.md "Nanotec set-up": ~59 ms before 'A'
    return caps;
}

namespace {
constexpr const char* kContext = "stepdeck::nanotec::Presentation";

struct BitText
{
    int bit;
    const char* name;
    const char* text;
    bool fault;
};

const BitText kStatusBits[] = {
    {0, "ready", QT_TRANSLATE_NOOP("stepdeck::nanotec::Presentation", "The drive is ready."),
     false},
    {1, "zero", QT_TRANSLATE_NOOP("stepdeck::nanotec::Presentation", "Zero position reached."),
     false},
    {2, "posError",
     QT_TRANSLATE_NOOP("stepdeck::nanotec::Presentation",
                       "Position error: the encoder disagrees with the demand position."),
     true},
    {3, "input1",
     QT_TRANSLATE_NOOP("stepdeck::nanotec::Presentation",
                       "Input 1 is still set while the drive is ready again."),
     false},
    {4, "mode0", QT_TRANSLATE_NOOP("stepdeck::nanotec::Presentation", "Mode, bit 0."), false},
    {5, "mode1", QT_TRANSLATE_NOOP("stepdeck::nanotec::Presentation", "Mode, bit 1."), false},
    {6, "mode2", QT_TRANSLATE_NOOP("stepdeck::nanotec::Presentation", "Mode, bit 2."), false},
};
} // namespace

ModelPresentation presentation()
{
    ModelPresentation p;
    p.statusWords = [](const QList<Axis>& axes) {
        QList<StatusWordInfo> words;
        for (Axis axis : axes) {
            StatusWordInfo w;
            w.key = QStringLiteral("status") + axisName(axis);
            w.title = QCoreApplication::translate("stepdeck::nanotec::Presentation",
                                                  "Drive status ($, 5.21)");
            w.axis = axis;
            w.width = 8;
            for (const BitText& b : kStatusBits) {
                StatusBitInfo info;
                info.bit = b.bit;
                info.name = QString::fromLatin1(b.name);
                info.description = QCoreApplication::translate(kContext, b.text);
                info.fault = b.fault;
                w.bits << info;
            }
            words << w;
        }
        return words;
    };
    p.formatTraffic = &genericFormatTraffic;
    p.trafficExample = [] {
        return QCoreApplication::translate("stepdeck::nanotec::Presentation",
                                           "Send a command, e.g. #1$ (status of drive 1) or #2Zo "
                                           "(top speed of drive 2); the final CR is added (1.1).");
    };
    // The console's send line: generic escapes; a missing final CR is added (1.1).
    p.parseTraffic = [](const QString& text, QByteArray* bytes, QString* error) {
        if (!genericParseTraffic(text, bytes, error))
            return false;
        if (!bytes->endsWith('\r'))
            *bytes += '\r';
        return true;
    };
    return p;
}

namespace {
// The registry's display name, shown through QCoreApplication::translate("Models", ...).
const char* const kDisplayName =
    QT_TRANSLATE_NOOP("Models", "Nanotec SMCI33 / SMCI47-S (RS485 bus)");
} // namespace

ModelInfo modelInfo()
{
    ModelInfo info;
    info.id = QStringLiteral("nanotec");
    info.displayName = QString::fromLatin1(kDisplayName);
    info.line = lineSettings();
    info.capabilities = capabilities(defaultAxisAddresses().keys());
    info.schema = parameterSchema();
    info.scenario = scenarioSupport();
    info.soak = soakProfile();
    info.presentation = presentation();
    info.logging = &lcNanotec;
    return describeModel<NanotecController, NanotecSimulator>(std::move(info));
}

} // namespace stepdeck::nanotec
