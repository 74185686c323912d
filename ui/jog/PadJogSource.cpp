#include "PadJogSource.h"
#include "jog/JoystickPad.h"
#include <QGuiApplication>

namespace stepdeck::ui {

PadJogSource::PadJogSource(JoystickPad* pad, std::optional<JogSlot> horizontal,
                           std::optional<JogSlot> vertical, QObject* parent)
    : JogInputSource(parent), m_pad(pad), m_horizontal(horizontal), m_vertical(vertical)
{
    connect(pad, &JoystickPad::deflectionChanged, this, &JogInputSource::changed);
    connect(pad, &JoystickPad::dragInterrupted, this, [this] {
        Q_EMIT interrupted(tr("Jog ended: the pad moved under the held pointer. Release the "
                              "button and press again."));
    });
}

QString PadJogSource::sourceName() const
{
    return m_pad ? tr("Pad %1").arg(m_pad->objectName()) : tr("Pad");
}

void PadJogSource::setResponse(const JogResponse& response)
{
    m_response = response;
    if (m_pad)
        m_pad->setDeadZone(response.deadZone);
    Q_EMIT changed();
}

SlotVelocities PadJogSource::heldDeflection()
{
    if (!m_pad || !m_pad->isDragging())
        return {};
    if (!(QGuiApplication::mouseButtons() & Qt::LeftButton)) {
        // The button is up but the pad never saw the release: end the drag now.
        m_pad->recenter();
        return {};
    }
    // The frame check runs here too, not only on pointer and move events: a renewal never
    // carries a deflection measured on a pad that has moved since the press.
    if (!m_pad->confirmFrameHeld())
        return {};
    const QPointF d = m_pad->deflection();
    SlotVelocities fractions;
    if (m_horizontal)
        fractions.insert(*m_horizontal, m_response.apply(d.x()));
    if (m_vertical)
        fractions.insert(*m_vertical, m_response.apply(d.y()));
    return fractions;
}

void PadJogSource::latch()
{
    if (m_pad)
        m_pad->recenter();
}

} // namespace stepdeck::ui
