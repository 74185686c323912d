#pragma once
#include "common/ElidedLabel.h"
#include "jog/JogSlot.h"
#include "model/MachineStatus.h"
#include <QWidget>

class QCheckBox;
class QComboBox;
class QGridLayout;
class QGroupBox;
class QScrollArea;
class QDialog;
class QLabel;
class QSlider;
class QTimer;

namespace stepdeck::ui {

class ConnectionGate;
class IncrementalJogWidget;
class JogController;
class JogVelocityReadout;
class JogSettingsWidget;
class JogStopDistanceLabel;
class JoystickPad;
class KeyboardJog;
class MachineContext;
class PadJogSource;

// The operator's main tool: the X/Y pad, Z (and U) sticks (with a machine open: its axes,
// JogAxisMap), incremental jog, keyboard jog,
// speed override, the live commanded velocity per axis and why a jog was refused.
class JogPanel : public QWidget
{
    Q_OBJECT
public:
    JogPanel(MachineContext* context, JogController* jog, KeyboardJog* keyboard,
             QWidget* parent = nullptr);

    JoystickPad* xyPad() const { return m_xy; }
    JoystickPad* zStick() const { return m_z; }
    JoystickPad* uStick() const { return m_u; }
    // With a machine open: the machine axis the other stick (and End/Home) jogs.
    QComboBox* otherStickAxis() const { return m_otherAxis; }
    JogVelocityReadout* velocityReadout() const { return m_velocity; }
    JogStopDistanceLabel* stopDistance() const { return m_stopDistance; }
    QCheckBox* keyboardCheck() const { return m_keyboardCheck; }
    QSlider* overrideSlider() const { return m_override; }
    QLabel* refusalLabel() const { return m_refusal; }
    QString keyboardStateText() const; // "Keyboard jog ON: ←/→ X, ...", "... paused ..."
    QLabel* jogModeNote() const { return m_jogModeNote; }
    IncrementalJogWidget* incremental() const { return m_incremental; }

    // The keyboard jog's keys and the axis each moves: "←/→ X, ↓/↑ Y, ..." (Help's shortcuts).
    QString keyboardLegend() const;

public Q_SLOTS:
    void releaseAll(); // pads back to centre and every jog input released

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    QWidget* buildSidePanel();
    QWidget* buildJogColumn(QWidget* parent);       // A: velocity, refusal, settings
    QWidget* buildKeyboardColumn(QWidget* parent);  // B: override, keyboard jog
    QGroupBox* buildSpeedOverride(QWidget* parent); // the slider and the stopping distance
    void fitSide(); // one column, or side by side where one does not fit the height
    void arrangeSide(bool sideBySide);
    int sideWidth(bool sideBySide) const; // the side's minimum width either way
    void rebuild();
    void onStatus();
    void showRefusal(const QString& reason);
    void showKeyboardState();
    QStringList keyboardStateTexts() const;    // every text m_keyboardState can show
    QMap<JogSlot, QString> slotLabels() const; // jog slot -> the axis it moves (JogAxisMap)

    MachineContext* m_context;
    JogController* m_jog;
    KeyboardJog* m_keyboard;
    JoystickPad* m_xy;
    JoystickPad* m_z;
    JoystickPad* m_u;
    QComboBox* m_otherAxis;
    QList<PadJogSource*> m_padSources;
    QSlider* m_override;
    QLabel* m_overrideValue;
    QCheckBox* m_keyboardCheck;
    ElidedLabel* m_keyboardState;
    ConnectionGate* m_gate = nullptr;
    ElidedLabel* m_refusal;
    QLabel* m_jogModeNote; // how jog works on models without a jog command
    QTimer* m_refusalTimer;
    JogVelocityReadout* m_velocity;
    JogStopDistanceLabel* m_stopDistance;
    IncrementalJogWidget* m_incremental;
    QDialog* m_settingsDialog;
    JogSettingsWidget* m_settings;
    QScrollArea* m_sideScroll = nullptr;
    QGridLayout* m_sideGrid = nullptr;
    QWidget* m_sideA = nullptr; // the velocity and the speed override
    QWidget* m_sideB = nullptr; // keyboard jog and the settings
    QWidget* m_sideC = nullptr; // incremental jog
    bool m_sideBySide = false;
};

} // namespace stepdeck::ui
