#pragma once
#include "jog/JogInputSource.h"
#include "jog/JogResponse.h"
#include <QPointer>
#include <optional>

namespace stepdeck::ui {

class JoystickPad;

// One on-screen pad or stick as a jog source. The drag proves itself held only while
// QGuiApplication::mouseButtons() still shows the left button down, read at every renewal:
// a mouse release that never reached the pad (grabbed by another window, lost by the window
// system) ends the drag there and then, as a release would. STOP, PANIC and focus loss
// re-centre the pad: the drag is over, and moving the still-held mouse moves nothing until
// the button is pressed again. So does a pad that moved or resized under the held pointer
// (JoystickPad::confirmFrameHeld, checked at every renewal as well).
class PadJogSource : public JogInputSource
{
    Q_OBJECT
public:
    // horizontal/vertical: the machine axes of the pad's two directions (a stick has only
    // a vertical one).
    PadJogSource(JoystickPad* pad, std::optional<JogSlot> horizontal,
                 std::optional<JogSlot> vertical, QObject* parent = nullptr);

    QString sourceName() const override;
    SlotVelocities heldDeflection() override;
    void latch() override;

    void setResponse(const JogResponse& response);
    JoystickPad* pad() const { return m_pad; }

Q_SIGNALS:
    // The drag was ended by the pad, not by the operator (it moved under the pointer).
    void interrupted(const QString& reason);

private:
    QPointer<JoystickPad> m_pad;
    std::optional<JogSlot> m_horizontal;
    std::optional<JogSlot> m_vertical;
    JogResponse m_response;
};

} // namespace stepdeck::ui
