#pragma once
#include "model/Capabilities.h"
#include <QCoreApplication>
#include <QMap>
#include <optional>

namespace stepdeck::bridge {

// How the laser's three motor axes map onto the controller behind the bridge. Laser axes are
// named by the axis byte of their frames ('1' X, '2' Y, '3' Z); controller axes by the
// controller's own names.
struct LaserBridgeConfig
{
    Q_DECLARE_TR_FUNCTIONS(LaserBridgeConfig)
public:
    static constexpr double kMaxScale = 1e6; // steps per laser unit

    QMap<Axis, Axis> axisMap{{Axis::X, Axis::X}, {Axis::Y, Axis::Y}, {Axis::Z, Axis::Z}};
    double scale = 1.0; // controller steps per laser unit; targets go to target x scale
    // Reference direction per controller axis (-1 or +1); axes not named: -1. Only for
    // controllers whose reference runs take a direction (Capabilities::referenceDirection).
    QMap<Axis, int> homeDirections;
    // A digital input of the controller wired to the door switch (1-based), if any.
    std::optional<int> doorInput;

    // What the bridge passes to ControllerSession::reference() for this axis: the configured
    // direction (default -1), or 1 ("reference this axis") where the controller chooses the
    // direction itself (EMIS 9.9), as the GUI's reference panel does.
    int referenceRequest(Axis controllerAxis, const Capabilities& controller) const
    {
        if (!controller.referenceDirection)
            return 1;
        return homeDirections.value(controllerAxis, -1);
    }

    // "1=X,2=Y,3=Z": laser axis number -> controller axis; a subset maps only those axes.
    static bool parseMap(const QString& text, QMap<Axis, Axis>* map, QString* error);
    // A decimal number of steps per laser unit, finite, > 0 and at most kMaxScale.
    static bool parseScale(const QString& text, double* scale, QString* error);
    // "X=-1,Y=1": reference direction per controller axis, -1 or +1.
    static bool parseHome(const QString& text, QMap<Axis, int>* directions, QString* error);
    static bool parseDoorInput(const QString& text, int* input, QString* error);

    // Against the controller behind: every mapped axis exists, none twice, directions only for
    // mapped axes and only where the controller's reference runs take one. Empty when fine,
    // else one sentence.
    QString validate(const Capabilities& controller) const;
    // "1=X,2=Y,3=Z" (the inverse of parseMap).
    QString mapText() const;
};

} // namespace stepdeck::bridge
