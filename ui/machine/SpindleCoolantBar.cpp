#include "SpindleCoolantBar.h"
#include "common/LedIndicator.h"
#include "controller/ControllerSession.h"
#include "machine/Machine.h"
#include "machine/MachineContext.h"
#include "motion/executors/SwitchExecutor.h"
#include "program/ProgramCheck.h"
#include "program/ProgramRules.h"
#include <QGridLayout>
#include <QPushButton>
#include <QSpinBox>
#include <cmath>

namespace stepdeck::ui {

namespace {
// The connected controller that switches the machine's spindle (has = &Capabilities::spindle)
// or coolant, as a program's M3/M8 reach it (motion::SwitchExecutor::switchController); null: none.
ControllerSession* switchSession(const machine::Machine* m, bool Capabilities::*has)
{
    if (!m)
        return nullptr;
    for (const machine::MachineController& c : m->description().controllers) {
        ControllerSession* s = m->session(c.id);
        if (s && s->capabilities().*has)
            return s->linkState() == LinkState::Connected ? s : nullptr;
    }
    return nullptr;
}
} // namespace

SpindleCoolantBar::SpindleCoolantBar(MachineContext* context, QWidget* parent)
    : QWidget(parent), m_context(context), m_spindle(new LedIndicator(QString(), this)),
      m_rpm(new QSpinBox(this)), m_spindleSwitch(new QPushButton(this)),
      m_coolant(new LedIndicator(QString(), this)), m_coolantSwitch(new QPushButton(this))
{
    setObjectName(QStringLiteral("spindleCoolantBar"));
    m_spindle->setObjectName(QStringLiteral("spindleState"));
    m_rpm->setObjectName(QStringLiteral("spindleRpm"));
    m_spindleSwitch->setObjectName(QStringLiteral("spindleSwitch"));
    m_coolant->setObjectName(QStringLiteral("coolantState"));
    m_coolantSwitch->setObjectName(QStringLiteral("coolantSwitch"));
    m_rpm->setRange(1, 100000);
    m_rpm->setValue(100000);
    m_rpm->setPrefix(tr("S "));
    m_rpm->setToolTip(tr("The speed the spindle switch starts it at, as a program's M3 S"));
    // Room for the longest text of each, so that nothing beside them moves when they change.
    const QFontMetrics fm = fontMetrics();
    const int onOff =
        std::max({fm.horizontalAdvance(tr("Spindle on")), fm.horizontalAdvance(tr("Spindle off")),
                  fm.horizontalAdvance(tr("Laser on")), fm.horizontalAdvance(tr("Laser off")),
                  fm.horizontalAdvance(tr("Coolant on")),
                  fm.horizontalAdvance(tr("Coolant off"))}) +
        24;
    m_spindleSwitch->setFixedWidth(onOff);
    m_coolantSwitch->setFixedWidth(onOff);
    const int state = std::max({fm.horizontalAdvance(tr("Spindle: unknown")),
                                fm.horizontalAdvance(tr("Laser: unknown")),
                                fm.horizontalAdvance(tr("Coolant: unknown"))}) +
                      28;
    m_spindle->setFixedWidth(state);
    m_coolant->setFixedWidth(state);
    m_spindleSwitch->setFocusPolicy(Qt::NoFocus);
    m_coolantSwitch->setFocusPolicy(Qt::NoFocus);
    // Two rows below the Position dock's read-out (the Run workspace, 1366x768).
    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->setHorizontalSpacing(6);
    grid->setVerticalSpacing(2);
    grid->addWidget(m_spindle, 0, 0);
    grid->addWidget(m_spindleSwitch, 0, 1);
    grid->addWidget(m_rpm, 0, 2);
    grid->addWidget(m_coolant, 1, 0);
    grid->addWidget(m_coolantSwitch, 1, 1);
    grid->setColumnStretch(3, 1);
    connect(m_spindleSwitch, &QPushButton::clicked, this, &SpindleCoolantBar::switchSpindle);
    connect(m_coolantSwitch, &QPushButton::clicked, this, &SpindleCoolantBar::switchCoolant);
    connect(m_context, &MachineContext::machineStatusChanged, this, &SpindleCoolantBar::refresh);
    connect(m_context, &MachineContext::machineChanged, this, &SpindleCoolantBar::refresh);
    refresh();
}

void SpindleCoolantBar::setProgramRunning(bool running)
{
    m_programRunning = running;
    refresh();
}

// The speed's range: 1..maxRpm in rpm with the machine file's spindle scale, else the
// controller's own values (E-LAB 1..1000, sent as written, as a program's S is).
void SpindleCoolantBar::fitSpeedRange(const machine::Machine* m, const ControllerSession* s)
{
    const std::optional<double> maxRpm = m ? m->description().spindle.maxRpm : std::nullopt;
    int top = 100000;
    if (maxRpm && *maxRpm >= 1) {
        top = int(std::min(*maxRpm, 1.0e6));
        // A laser's S is its power, scaled as a spindle's: no rpm (issue 50 item 5).
        m_rpm->setSuffix(m->description().spindle.laser ? QString() : tr(" rpm"));
    } else {
        const ParameterSchema schema = s->schema();
        const Capabilities caps = s->capabilities();
        if (const ParameterSpec* spec =
                caps.spindleSpeedParameter
                    ? schema.find(QString::fromLatin1(caps.spindleSpeedParameter))
                    : nullptr;
            spec && spec->maximum >= 1)
            top = int(std::min<double>(spec->maximum, 1.0e6));
        m_rpm->setSuffix(QString()); // the controller's own unit: no scale in the machine file
    }
    if (m_rpm->maximum() != top) {
        m_rpm->setRange(1, top);
        m_rpm->setValue(top);
    }
}

void SpindleCoolantBar::refresh()
{
    const machine::Machine* m = m_context->machine();
    const ControllerSession* spindle = switchSession(m, &Capabilities::spindle);
    if (spindle)
        fitSpeedRange(m, spindle);
    const ControllerSession* coolant = switchSession(m, &Capabilities::coolant);
    using State = LedIndicator::State;
    // A laser on the spindle output (issue 50 item 5): M3/M5 switch its beam, S is its power.
    const bool laser = m && m->description().spindle.laser;
    if (spindle) {
        const bool on = spindle->status().spindleOn; // read back (tmSpindleOn)
        m_spindle->setState(on ? State::On : State::Off);
        m_spindle->setText(laser ? (on ? tr("Laser: on") : tr("Laser: off"))
                                 : (on ? tr("Spindle: on") : tr("Spindle: off")));
        m_spindle->setToolTip(tr("As the controller reports it"));
        m_spindleSwitch->setText(laser ? (on ? tr("Laser off") : tr("Laser on"))
                                       : (on ? tr("Spindle off") : tr("Spindle on")));
    } else {
        m_spindle->setState(State::Unknown);
        m_spindle->setText(laser ? tr("Laser: unknown") : tr("Spindle: unknown"));
        m_spindle->setToolTip(m ? tr("No connected controller of this machine has a spindle")
                                : tr("No machine is open"));
        m_spindleSwitch->setText(laser ? tr("Laser on") : tr("Spindle on"));
    }
    m_rpm->setToolTip(laser ? tr("The power the laser switch turns the beam on at, as a "
                                 "program's M3 S")
                            : tr("The speed the spindle switch starts it at, as a program's M3 S"));
    std::optional<bool> coolantOn;
    if (coolant)
        if (const auto it = coolant->status().knownParameters.constFind(QStringLiteral("coolant"));
            it != coolant->status().knownParameters.cend())
            coolantOn = it->global.toBool();
    m_coolant->setState(!coolantOn ? State::Unknown : *coolantOn ? State::On : State::Off);
    m_coolant->setText(!coolantOn   ? tr("Coolant: unknown")
                       : *coolantOn ? tr("Coolant: on")
                                    : tr("Coolant: off"));
    m_coolant->setToolTip(coolant ? tr("As last switched in this session: the controller cannot "
                                       "read its relay back")
                                  : tr("No connected controller of this machine has coolant"));
    m_coolantSwitch->setText(coolantOn.value_or(false) ? tr("Coolant off") : tr("Coolant on"));
    const bool free = !m_programRunning && m && m->state() != machine::MachineState::Moving;
    m_spindleSwitch->setEnabled(spindle && free);
    m_rpm->setEnabled(spindle && free);
    m_coolantSwitch->setEnabled(coolant && free);
}

void SpindleCoolantBar::switchSpindle()
{
    const machine::Machine* m = m_context->machine();
    ControllerSession* s = switchSession(m, &Capabilities::spindle);
    if (!s || m_programRunning)
        return;
    if (s->status().spindleOn) {
        s->setSpindle(0);
        return;
    }
    // As M3 S would be sent: scaled by the machine file's maxRpm, refused as the check would.
    const std::optional<double> maxRpm = m->description().spindle.maxRpm;
    const QString why = motion::SwitchExecutor::spindleSpeed(s->capabilities(), s->schema(), maxRpm,
                                                             m_rpm->value());
    if (!why.isEmpty()) {
        m_spindle->setToolTip(why);
        return;
    }
    s->setSpindle(motion::SwitchExecutor::spindleValue(s->capabilities(), s->schema(), maxRpm,
                                                       m_rpm->value()));
}

void SpindleCoolantBar::switchCoolant()
{
    ControllerSession* s = switchSession(m_context->machine(), &Capabilities::coolant);
    if (!s || m_programRunning)
        return;
    const auto it = s->status().knownParameters.constFind(QStringLiteral("coolant"));
    const bool on = it != s->status().knownParameters.cend() && it->global.toBool();
    s->setCoolant(!on);
}

QString SpindleCoolantBar::spindleText() const
{
    return m_spindle->text();
}

QString SpindleCoolantBar::coolantText() const
{
    return m_coolant->text();
}

} // namespace stepdeck::ui
