#include "LaserModel.h"
#include "LaserAxisController.h"
#include "LaserAxisSimulator.h"
#include "LaserCodec.h"
#include "LaserLogging.h"
#include <QCoreApplication>

namespace stepdeck::laser {

Q_LOGGING_CATEGORY(lcLaser, "stepdeck.laser", QtWarningMsg)

Capabilities capabilities()
{
    Capabilities caps;
    caps.axes = {Axis::X, Axis::Y, Axis::Z}; // "up to 3 motoraxis"
    // Relative moves are converted to targets from the last reported position.
    caps.motionModes = {MotionMode::RelativeMove, MotionMode::AbsoluteMove, MotionMode::Reference};
    caps.positionReadback = true; // "actual-position" in every status response
    caps.rampedStop = false;
    caps.stopCommand = false; // only "move to home" and "move to position" exist
    caps.panic = false;
    caps.statusQuery = false;          // "The axis can send at any time a status response"
    caps.reportsArrival = true;        // "... after having reached its last commanded target"
    caps.jogByTargets = true;          // no jog command: short targets one after the other
    caps.relativeNeedsPosition = true; // LaserAxisMotion::moveRelative: targets only
    caps.doorSwitch = true;            // status '3' door opened, '4' door closed
    // "target-position [0...99999]": a number without a unit (the axis gives it meaning).
    caps.positionUnit = QT_TRANSLATE_NOOP("Units", "units");
    // Position units per second a jog target may cover per second of stick deflection; the
    // protocol has no speed, so this only sizes the short targets.
    caps.maxJogSpeed = 2000;
    caps.defaultJogAcceleration = 1e9; // no host ramp: each target is a move of its own
    // No rate: the protocol's move frame carries a target only (feedRateParameter stays null).
    return caps;
}

ModelPresentation presentation()
{
    ModelPresentation p;
    p.formatTraffic = &genericFormatTraffic;
    p.parseTraffic = [](const QString& text, QByteArray* bytes, QString* error) {
        if (!genericParseTraffic(text, bytes, error))
            return false;
        if (!bytes->endsWith(kCr))
            *bytes += kCr;
        return true;
    };
    return p;
}

ModelInfo modelInfo()
{
    ModelInfo info;
    info.id = QStringLiteral("laser-axis");
    // Shown through QCoreApplication::translate("Models", ...).
    info.displayName =
        QString::fromUtf8(QT_TRANSLATE_NOOP("Models", "Laser marker motor axes (RS232)"));
    info.line = lineSettings();
    info.capabilities = capabilities();
    info.schema = ParameterSchema{};
    info.scenario = scenarioSupport();
    info.soak = soakProfile();
    info.presentation = presentation();
    info.logging = &lcLaser;
    return describeModel<LaserAxisController, LaserAxisSimulator>(std::move(info));
}

} // namespace stepdeck::laser
