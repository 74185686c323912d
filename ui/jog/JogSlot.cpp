#include "JogSlot.h"

namespace stepdeck::ui {

const QList<JogSlot>& allJogSlots()
{
    static const QList<JogSlot> list{JogSlot::PadHorizontal, JogSlot::PadVertical, JogSlot::ZStick,
                                     JogSlot::OtherStick};
    return list;
}

QString jogSlotKey(JogSlot slot)
{
    switch (slot) {
    case JogSlot::PadHorizontal:
        return QStringLiteral("X");
    case JogSlot::PadVertical:
        return QStringLiteral("Y");
    case JogSlot::ZStick:
        return QStringLiteral("Z");
    case JogSlot::OtherStick:
        return QStringLiteral("U");
    }
    return {};
}

} // namespace stepdeck::ui
