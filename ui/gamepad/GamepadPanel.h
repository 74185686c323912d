#pragma once
#include "jog/JogSlot.h"
#include <QWidget>

class QCheckBox;
class QComboBox;
class QFormLayout;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace stepdeck::ui {

class ElidedLabel;
class GamepadJogSource;
class JogAxisMap;
class LedIndicator;

// Settings and live view of the physical gamepad: device and dead-man state, stick-to-axis
// mapping with inversion, dead zone, calibration, and the raw stick positions.
class GamepadPanel : public QWidget
{
    Q_OBJECT
public:
    // jogSlots: what each stick mapping row moves (with a machine open, its axis names); may
    // be null (rows named X, Y, Z, U).
    GamepadPanel(GamepadJogSource* source, JogAxisMap* jogSlots, QWidget* parent = nullptr);
    QString rowName(JogSlot slot) const; // what the stick mapping row of a slot moves

    QString deviceText() const;

private:
    void refresh();
    void toggleCalibration();
    void nameRows();

    GamepadJogSource* m_source;
    JogAxisMap* m_slots;
    ElidedLabel* m_device;
    LedIndicator* m_deadmanLed;
    QCheckBox* m_enabled;
    QSpinBox* m_deadman;
    QSpinBox* m_deadZone;
    QPushButton* m_calibrate;
    ElidedLabel* m_hint;
    QMap<JogSlot, QLabel*> m_rowName;
    QMap<JogSlot, QComboBox*> m_binding;
    QMap<JogSlot, QCheckBox*> m_invert;
    QList<QProgressBar*> m_bars;
    QFormLayout* m_rawForm;
};

} // namespace stepdeck::ui
