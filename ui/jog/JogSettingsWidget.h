#pragma once
#include "jog/JogResponse.h"
#include "jog/JogSlot.h"
#include <QGroupBox>

class QComboBox;
class QFormLayout;
class QSpinBox;

namespace stepdeck::ui {

class JogController;
class KeyboardJog;
class MachineContext;

// Max jog speed per axis (with a machine open: per machine axis on a jog slot, in unit/s), the
// pad's dead zone and response curve, and the keyboard speed. Persisted with QSettings.
class JogSettingsWidget : public QGroupBox
{
    Q_OBJECT
public:
    JogSettingsWidget(MachineContext* context, JogController* jog, KeyboardJog* keyboard,
                      QWidget* parent = nullptr);

    JogResponse response() const { return m_response; }

public Q_SLOTS:
    void rebuild();

Q_SIGNALS:
    void responseChanged(const stepdeck::ui::JogResponse& response);

private:
    void storeResponse();
    void addMachineRows();

    MachineContext* m_context;
    JogController* m_jog;
    KeyboardJog* m_keyboard;
    JogResponse m_response;
    QFormLayout* m_form;
    QSpinBox* m_deadZone;
    QComboBox* m_curve;
    QSpinBox* m_keyboardSpeed;
    QList<QWidget*> m_axisRows;
};

} // namespace stepdeck::ui
