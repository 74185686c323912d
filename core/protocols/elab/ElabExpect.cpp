#include "ElabExpect.h"

namespace stepdeck::elab {

bool expectMatches(Expect expect, Reply::Kind kind)
{
    switch (expect) {
    case Expect::None:
        return false;
    case Expect::Ack:
        return kind == Reply::Kind::Ack;
    case Expect::AckNak:
        return kind == Reply::Kind::Ack || kind == Reply::Kind::Nak;
    case Expect::MachineState:
        return kind == Reply::Kind::MachineState;
    case Expect::AxeState:
        return kind == Reply::Kind::AxeState;
    case Expect::Temperature:
        return kind == Reply::Kind::Temperature;
    case Expect::RelPosition:
        return kind == Reply::Kind::RelPosition;
    }
    return false;
}

QString expectName(Expect expect)
{
    switch (expect) {
    case Expect::None:
        return QStringLiteral("nothing");
    case Expect::Ack:
        return QStringLiteral("<ACK>");
    case Expect::AckNak:
        return QStringLiteral("<ACK>/<NAK>");
    case Expect::MachineState:
        return QStringLiteral("<ENQ>BBBB#");
    case Expect::AxeState:
        return QStringLiteral("<HT>BB#");
    case Expect::Temperature:
        return QStringLiteral("<ETB>TT#");
    case Expect::RelPosition:
        return QStringLiteral("<ETX>X,Y;Z.");
    }
    return {};
}

Expect expectFor(const QByteArray& frame)
{
    if (frame.isEmpty())
        return Expect::None;
    switch (frame.at(0)) {
    case ctrl::ENQ:
        return Expect::MachineState;
    case ctrl::HT:
        return Expect::AxeState;
    case ctrl::ETB:
        return Expect::Temperature;
    case ctrl::ETX:
        return Expect::RelPosition;
    case ctrl::SYN: // RequestSync: "akzeptiert den Befehl, schickt aber keine Antwort"
    case ctrl::DC2: // SetFeedStepXYZ: "grundsätzlich keine Antwort"
        return Expect::None;
    default:
        return Expect::AckNak;
    }
}

} // namespace stepdeck::elab
