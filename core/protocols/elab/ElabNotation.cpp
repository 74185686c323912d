#include "ElabCodec.h"
#include <QCoreApplication>

// Human-readable notation of the E-LAB protocol: the manual's status bit names and the
// control-character mnemonics of its "Steuerzeichen Tabelle" (traffic console, NAK reasons).
namespace stepdeck::elab {

namespace {
QString describeBits(quint32 word, const QList<BitName>& names)
{
    QStringList parts;
    for (const BitName& b : names) {
        if (word & (1u << b.bit))
            parts << QStringLiteral("%1 (%2)").arg(QLatin1String(b.name), Codec::tr(b.description));
    }
    return parts.isEmpty() ? Codec::tr("none") : parts.join(QStringLiteral(", "));
}

} // namespace

const QList<BitName>& machineStateBits()
{
    // RequestMachineState: "In dem Status hat jedes Bit eine spezielle Information".
    static const QList<BitName> bits{
        {0, "tmDriveOn", QT_TRANSLATE_NOOP("stepdeck::elab::Codec", "motors are powered")},
        {1, "tmSpindleOn", QT_TRANSLATE_NOOP("stepdeck::elab::Codec", "spindle motor is on")},
        {2, "tmBusy", QT_TRANSLATE_NOOP("stepdeck::elab::Codec", "axes are moving")},
        {3, "tmCOMfail",
         QT_TRANSLATE_NOOP("stepdeck::elab::Codec", "serial port fault (not implemented)")},
        {4, "tmTimeOut",
         QT_TRANSLATE_NOOP("stepdeck::elab::Codec", "internal error (not implemented)")},
        {5, "tmParmError",
         QT_TRANSLATE_NOOP("stepdeck::elab::Codec", "parameter error (not implemented)")},
        {6, "tmOverTemp",
         QT_TRANSLATE_NOOP("stepdeck::elab::Codec", "internal temperature above 50 °C")},
        {7, "tmInvSetup",
         QT_TRANSLATE_NOOP(
             "stepdeck::elab::Codec",
             "setup incomplete: start speed, max speed and acceleration not all set")},
        {8, "tmLimSwX",
         QT_TRANSLATE_NOOP("stepdeck::elab::Codec", "a limit switch of the X axis is active")},
        {9, "tmLimSwY",
         QT_TRANSLATE_NOOP("stepdeck::elab::Codec", "a limit switch of the Y axis is active")},
        {10, "tmLimSwZ",
         QT_TRANSLATE_NOOP("stepdeck::elab::Codec", "a limit switch of the Z axis is active")},
        {11, "tmRefSwX",
         QT_TRANSLATE_NOOP("stepdeck::elab::Codec", "the X reference switch is active")},
        {12, "tmRefSwY",
         QT_TRANSLATE_NOOP("stepdeck::elab::Codec", "the Y reference switch is active")},
        {13, "tmRefSwZ",
         QT_TRANSLATE_NOOP("stepdeck::elab::Codec", "the Z reference switch is active")},
        {14, "tmPanicStop",
         QT_TRANSLATE_NOOP("stepdeck::elab::Codec", "the panic (emergency stop) switch is active")},
    };
    return bits;
}

const QList<BitName>& axeStateBits()
{
    // RequestAxeState: "Lese den Status der Achsen".
    static const QList<BitName> bits{
        {0, "taXMove",
         QT_TRANSLATE_NOOP("stepdeck::elab::Codec", "X axis in FastMove or feed mode")},
        {1, "taXJog", QT_TRANSLATE_NOOP("stepdeck::elab::Codec", "X axis in jog mode")},
        {2, "taYMove",
         QT_TRANSLATE_NOOP("stepdeck::elab::Codec", "Y axis in FastMove or feed mode")},
        {3, "taYJog", QT_TRANSLATE_NOOP("stepdeck::elab::Codec", "Y axis in jog mode")},
        {4, "taZMove",
         QT_TRANSLATE_NOOP("stepdeck::elab::Codec", "Z axis in FastMove or feed mode")},
        {5, "taZJog", QT_TRANSLATE_NOOP("stepdeck::elab::Codec", "Z axis in jog mode")},
        {6, "taLimSw", QT_TRANSLATE_NOOP("stepdeck::elab::Codec", "a limit switch is active")},
        {7, "taRefSw", QT_TRANSLATE_NOOP("stepdeck::elab::Codec", "a reference switch is active")},
    };
    return bits;
}

QString describeMachineState(quint16 word)
{
    return describeBits(word, machineStateBits());
}
QString describeAxeState(quint8 byte)
{
    return describeBits(byte, axeStateBits());
}

// ------------------------------------------------------------------ mnemonics

const char* mnemonic(quint8 controlByte)
{
    // The manual's table names 0x11 XON and 0x13 XOFF (not DC1/DC3).
    static const char* const names[32] = {"NUL", "SOH", "STX", "ETX",  "EOT", "ENQ", "ACK", "BEL",
                                          "BS",  "HT",  "LF",  "VT",   "FF",  "CR",  "SO",  "SI",
                                          "DLE", "XON", "DC2", "XOFF", "DC4", "NAK", "SYN", "ETB",
                                          "CAN", "EM",  "SUB", "ESC",  "FS",  "GS",  "RS",  "US"};
    return controlByte < 32 ? names[controlByte] : nullptr;
}

static QString hexMnemonic(quint8 b)
{
    return QStringLiteral("<x%1>").arg(
        QString::number(b, 16).toUpper().rightJustified(2, QLatin1Char('0')));
}

QString toMnemonics(const QByteArray& bytes)
{
    QString out;
    bool afterDc2 = false;
    for (char c : bytes) {
        const quint8 b = quint8(c);
        if (afterDc2) {
            // The DC2 data byte is binary: show it as hex so 0x10..0x1F are not read as
            // control characters.
            out += hexMnemonic(b);
            afterDc2 = false;
        } else if (b < 32) {
            out += QLatin1Char('<') + QLatin1String(mnemonic(b)) + QLatin1Char('>');
            afterDc2 = c == ctrl::DC2;
        } else if (b < 127 && c != '<') {
            out += QLatin1Char(c);
        } else {
            out += hexMnemonic(b);
        }
    }
    return out;
}

bool fromMnemonics(const QString& text, QByteArray* bytes, QString* error)
{
    QByteArray out;
    for (int i = 0; i < text.size(); ++i) {
        const QChar ch = text.at(i);
        if (ch != QLatin1Char('<')) {
            if (ch.unicode() > 126) {
                *error = Codec::tr("character %1 at position %2 is not ASCII").arg(ch).arg(i + 1);
                return false;
            }
            out += char(ch.unicode());
            continue;
        }
        const int end = text.indexOf(QLatin1Char('>'), i);
        if (end < 0) {
            *error = Codec::tr("'<' at position %1 is not closed").arg(i + 1);
            return false;
        }
        const QString name = text.mid(i + 1, end - i - 1).toUpper();
        bool found = false;
        if (name.startsWith(QLatin1Char('X')) && name.size() == 3) {
            bool ok = false;
            const int v = name.mid(1).toInt(&ok, 16);
            if (ok) {
                out += char(v);
                found = true;
            }
        }
        for (int b = 0; b < 32 && !found; ++b) {
            if (name == QLatin1String(mnemonic(quint8(b))) ||
                (b == 0x11 && name == QLatin1String("DC1")) ||
                (b == 0x13 && name == QLatin1String("DC3"))) {
                out += char(b);
                found = true;
            }
        }
        if (!found) {
            *error = Codec::tr("unknown mnemonic <%1> at position %2").arg(name).arg(i + 1);
            return false;
        }
        i = end;
    }
    *bytes = out;
    return true;
}

} // namespace stepdeck::elab
