#include "GamepadJogSource.h"
#include "gamepad/GamepadDevice.h"
#include <QSettings>

namespace stepdeck::ui {

double AxisCalibration::apply(double raw) const
{
    const double v = raw - centre;
    const double span = v >= 0 ? maximum - centre : centre - minimum;
    if (span <= 1e-6)
        return 0.0;
    return qBound(-1.0, v / span, 1.0);
}

GamepadJogSource::GamepadJogSource(GamepadDevice* device, QObject* parent)
    : JogInputSource(parent), m_device(device)
{
    // SDL game-controller layout: left stick X/Y for X/Y, right stick Y for Z, right stick X
    // for U. SDL reports stick Y positive downwards, hence the inversion. Dead-man: left
    // shoulder button (SDL_CONTROLLER_BUTTON_LEFTSHOULDER = 9).
    m_bindings.insert(JogSlot::PadHorizontal, {0, false});
    m_bindings.insert(JogSlot::PadVertical, {1, true});
    m_bindings.insert(JogSlot::ZStick, {3, true});
    m_bindings.insert(JogSlot::OtherStick, {2, false});
    m_response.deadZone = 0.12; // physical sticks rarely rest at exactly zero
    m_clock.start();
    // Every change is a sample too.
    connect(device, &GamepadDevice::connectedChanged, this, [this] {
        onSample();
        update();
    });
    connect(device, &GamepadDevice::axisChanged, this, [this](int index, double value) {
        if (m_calibrating) {
            AxisCalibration& c = m_calibration[index];
            c.minimum = qMin(c.minimum, value);
            c.maximum = qMax(c.maximum, value);
        }
        onSample();
        update();
    });
    connect(device, &GamepadDevice::buttonChanged, this, [this] {
        onSample();
        update();
    });
    connect(device, &GamepadDevice::sampled, this, &GamepadJogSource::onSample);
}

void GamepadJogSource::onSample()
{
    const bool wasProven = isProven();
    if (deadmanHeld())
        m_provenMs = m_clock.elapsed();
    // A sample only renews the proof; the controller re-reads it at its next renewal. Only a
    // proof that had lapsed needs a report (the axes may move again).
    if (!wasProven && isProven() && !m_last.isEmpty())
        Q_EMIT changed();
}

bool GamepadJogSource::isProven() const
{
    return m_provenMs >= 0 && m_clock.elapsed() - m_provenMs <= kSampleWindowMs;
}

SlotVelocities GamepadJogSource::heldDeflection()
{
    if (m_last.isEmpty()) {
        m_latched = false; // back in neutral (or dead-man released): the latch is over
        return {};
    }
    if (m_latched || !isProven())
        return {};
    return m_last;
}

void GamepadJogSource::latch()
{
    m_latched = !m_last.isEmpty();
    Q_EMIT changed();
}

void GamepadJogSource::setEnabled(bool enabled)
{
    m_enabled = enabled;
    update();
}

void GamepadJogSource::setDeadmanButton(int button)
{
    m_deadman = button;
    update();
}

bool GamepadJogSource::deadmanHeld() const
{
    return m_device && m_device->isConnected() && m_deadman >= 0 && m_device->button(m_deadman);
}

void GamepadJogSource::setResponse(const JogResponse& response)
{
    m_response = response;
    update();
}

void GamepadJogSource::setBinding(JogSlot axis, const StickBinding& binding)
{
    m_bindings.insert(axis, binding);
    update();
}

void GamepadJogSource::startCalibration()
{
    m_calibrating = true;
    m_calibration.clear();
    if (m_device) {
        for (int i = 0; i < m_device->axisCount(); ++i) {
            const double rest = m_device->axis(i);
            m_calibration.insert(i, AxisCalibration{rest, rest, rest});
        }
    }
    update(); // no motion while calibrating
}

void GamepadJogSource::finishCalibration()
{
    m_calibrating = false;
    // An axis that was never moved keeps the full range around its rest position.
    for (AxisCalibration& c : m_calibration) {
        if (c.maximum - c.centre < 0.2)
            c.maximum = 1.0;
        if (c.centre - c.minimum < 0.2)
            c.minimum = -1.0;
    }
    saveSettings();
    update();
}

SlotVelocities GamepadJogSource::readSticks() const
{
    SlotVelocities fractions;
    // No dead-man, no motion: the button must be held for as long as the axes move.
    if (m_enabled && !m_calibrating && deadmanHeld()) {
        for (auto it = m_bindings.cbegin(); it != m_bindings.cend(); ++it) {
            const StickBinding& b = it.value();
            if (b.index < 0 || b.index >= m_device->axisCount())
                continue;
            const AxisCalibration c = m_calibration.value(b.index);
            double v = m_response.apply(c.apply(m_device->axis(b.index)));
            if (b.invert)
                v = -v;
            if (v != 0.0)
                fractions.insert(it.key(), v);
        }
    }
    return fractions;
}

void GamepadJogSource::update()
{
    const SlotVelocities fractions = readSticks();
    if (fractions.isEmpty())
        m_latched = false;
    if (fractions != m_last) {
        m_last = fractions;
        Q_EMIT changed();
    }
    Q_EMIT stateChanged();
}

void GamepadJogSource::loadSettings()
{
    const QSettings s;
    m_enabled = s.value(QStringLiteral("gamepad/enabled"), true).toBool();
    m_deadman = s.value(QStringLiteral("gamepad/deadman"), m_deadman).toInt();
    m_response.deadZone =
        s.value(QStringLiteral("gamepad/deadZone"), m_response.deadZone).toDouble();
    m_response.exponent =
        s.value(QStringLiteral("gamepad/exponent"), m_response.exponent).toDouble();
    for (JogSlot a : allJogSlots()) {
        const QString key = QStringLiteral("gamepad/binding/%1/").arg(jogSlotKey(a));
        StickBinding b = m_bindings.value(a);
        b.index = s.value(key + QStringLiteral("index"), b.index).toInt();
        b.invert = s.value(key + QStringLiteral("invert"), b.invert).toBool();
        m_bindings.insert(a, b);
    }
    const QVariantList cal = s.value(QStringLiteral("gamepad/calibration")).toList();
    m_calibration.clear();
    for (int i = 0; i < cal.size(); ++i) {
        const QVariantList c = cal.at(i).toList();
        if (c.size() == 3)
            m_calibration.insert(i, {c[0].toDouble(), c[1].toDouble(), c[2].toDouble()});
    }
    update();
}

void GamepadJogSource::saveSettings() const
{
    QSettings s;
    s.setValue(QStringLiteral("gamepad/enabled"), m_enabled);
    s.setValue(QStringLiteral("gamepad/deadman"), m_deadman);
    s.setValue(QStringLiteral("gamepad/deadZone"), m_response.deadZone);
    s.setValue(QStringLiteral("gamepad/exponent"), m_response.exponent);
    for (auto it = m_bindings.cbegin(); it != m_bindings.cend(); ++it) {
        const QString key = QStringLiteral("gamepad/binding/%1/").arg(jogSlotKey(it.key()));
        s.setValue(key + QStringLiteral("index"), it.value().index);
        s.setValue(key + QStringLiteral("invert"), it.value().invert);
    }
    QVariantList cal;
    const int n = m_calibration.isEmpty() ? 0 : m_calibration.lastKey() + 1;
    for (int i = 0; i < n; ++i) {
        const AxisCalibration c = m_calibration.value(i);
        cal << QVariant(QVariantList{c.centre, c.minimum, c.maximum});
    }
    s.setValue(QStringLiteral("gamepad/calibration"), cal);
}

} // namespace stepdeck::ui
