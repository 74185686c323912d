#include "MachineStatus.h"
#include <QJsonArray>

namespace stepdeck {

bool MachineStatus::anyLimitSwitch() const
{
    for (const AxisStatus& a : axes) {
        if (a.limitSwitch)
            return true;
    }
    return false;
}

bool MachineStatus::anyMoving() const
{
    for (const AxisStatus& a : axes) {
        if (a.moving || a.jogging || a.motionUnknown)
            return true;
    }
    return busy;
}

QJsonObject MachineStatus::toJson(const QString& modelId) const
{
    QJsonObject machine{{"driveOn", driveOn},
                        {"spindleOn", spindleOn},
                        {"busy", busy},
                        {"overTemperature", overTemperature},
                        {"setupIncomplete", setupIncomplete},
                        {"panic", panic},
                        {"commFault", commFault},
                        {"motionUnconfirmed", motionUnconfirmed}};
    if (startButton)
        machine.insert("startButton", *startButton);
    if (doorOpen)
        machine.insert("doorOpen", *doorOpen);
    QJsonObject axesJson;
    for (auto it = axes.cbegin(); it != axes.cend(); ++it) {
        const AxisStatus& a = it.value();
        QJsonObject axis{{"moving", a.moving},
                         {"jogging", a.jogging},
                         {"limitSwitch", a.limitSwitch},
                         {"referenceSwitch", a.referenceSwitch},
                         {"referenced", a.referenced},
                         {"position", double(a.position)},
                         {"positionKnown", a.positionKnown},
                         {"positionEstimated", a.positionEstimated},
                         {"motionUnknown", a.motionUnknown}};
        if (a.lastSwitch != SwitchEvent::None)
            axis.insert("lastSwitch", a.lastSwitch == SwitchEvent::Limit ? "limit" : "reference");
        axesJson.insert(axisName(it.key()), axis);
    }
    QJsonObject out{{"model", modelId}, {"machine", machine}, {"axes", axesJson}};
    out.insert("temperatureCelsius",
               temperatureCelsius ? QJsonValue(*temperatureCelsius) : QJsonValue());
    if (!drives.isEmpty()) {
        QJsonArray drivesJson;
        for (const DriveStatus& d : drives) {
            QJsonArray driveAxes;
            for (Axis a : d.axes)
                driveAxes.append(axisName(a));
            drivesJson.append(QJsonObject{{"address", d.address},
                                          {"axes", driveAxes},
                                          {"responding", d.responding},
                                          {"firmware", d.firmware},
                                          {"detail", d.detail}});
        }
        out.insert("drives", drivesJson);
    }
    if (inputs) {
        QJsonArray levels;
        for (bool level : *inputs)
            levels.append(level);
        out.insert("inputs", levels);
    }
    if (!outputs.isEmpty()) {
        QJsonArray states;
        for (const std::optional<bool>& state : outputs)
            states.append(state ? QJsonValue(*state) : QJsonValue());
        out.insert("outputs", states);
    }
    if (!deviceFirmware.isEmpty())
        out.insert("device", QJsonObject{{"firmware", deviceFirmware}});
    out.insert("raw", QJsonObject::fromVariantMap(raw));
    return out;
}

} // namespace stepdeck
