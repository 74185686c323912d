#pragma once
#include "model/Axis.h"
#include <QByteArray>
#include <QCoreApplication>
#include <QList>
#include <QString>
#include <functional>
#include <optional>

namespace stepdeck {

// How a model's own data is shown to people, without the UI knowing any protocol bytes.
// Every member is optional: a model that leaves one empty gets the generic presentation
// (raw words in hex without bit names, traffic as ASCII with escapes).

// One bit of a raw status word, with the manual's name and plain words for a tooltip.
struct StatusBitInfo
{
    int bit = 0;
    QString name;            // the manual's name, e.g. "tmDriveOn" (never translated)
    QString description;     // plain words, already translated, e.g. "the motors are powered"
    bool implemented = true; // false: documented but the firmware never sets it
    bool fault = false;      // shown as a warning/error colour when set
};

// A raw status word as published in MachineStatus::raw under `key`.
struct StatusWordInfo
{
    QString key;    // key in MachineStatus::raw, e.g. "machineState"
    QString title;  // translated heading, e.g. "Machine state (RequestMachineState)"
    int width = 16; // bits, for the hex display width
    QList<StatusBitInfo> bits;
    // The axis a word of one drive belongs to (Nanotec `$` of each drive); nullopt: a word of
    // the controller. The title then names no axis: the view says whose word it shows.
    std::optional<Axis> axis;
};

struct ModelPresentation
{
    // The raw words with their bit names for a controller of `axes`, built when called so the
    // current language applies (a bus of 254 drives has 254 drive words; issue 32).
    std::function<QList<StatusWordInfo>(const QList<Axis>& axes)> statusWords;
    // Traffic bytes as console text (E-LAB: "<ESC>S0064,0064;0064.").
    std::function<QString(const QByteArray&)> formatTraffic;
    // The console's send line back into bytes; false and a reason on bad notation.
    std::function<bool(const QString&, QByteArray*, QString*)> parseTraffic;
    // The send line's hint: an example in the model's own notation, already translated (issue
    // 31: the E-LAB's showed on every model). Unset: the generic notation's hint.
    std::function<QString()> trafficExample;
    // Models with input programs (Capabilities::inputPrograms): why one command line cannot be
    // part of a program (grammar, range, kind), already translated; empty when it can.
    std::function<QString(const QString&)> checkProgramCommand;
    // Models without a stop command (Capabilities::stopCommand false): what stops the
    // controller instead and what the host does afterwards, already translated, short (it
    // stands permanently next to STOP/PANIC instead of Controller::noStopCommandText()), and
    // the longer explanation for its tooltip.
    std::function<QString()> noStopNote;
    std::function<QString()> noStopNoteDetail;
};

// Generic notation for ASCII protocols: printable bytes as they are, "\r", "\n", "\t" and
// "\\" escaped, everything else as <xNN>.
inline QString genericFormatTraffic(const QByteArray& bytes)
{
    QString out;
    out.reserve(bytes.size());
    for (char c : bytes) {
        const auto b = static_cast<unsigned char>(c);
        if (b == '\r')
            out += QStringLiteral("\\r");
        else if (b == '\n')
            out += QStringLiteral("\\n");
        else if (b == '\t')
            out += QStringLiteral("\\t");
        else if (b == '\\')
            out += QStringLiteral("\\\\");
        else if (b == '<')
            out += QStringLiteral("<x3C>");
        else if (b >= 0x20 && b < 0x7F)
            out += QChar(b);
        else
            out += QStringLiteral("<x%1>").arg(
                QString::number(b, 16).toUpper().rightJustified(2, QLatin1Char('0')));
    }
    return out;
}

// Reverse of genericFormatTraffic for the console's send line.
inline bool genericParseTraffic(const QString& text, QByteArray* bytes, QString* error)
{
    QByteArray out;
    for (int i = 0; i < text.size(); ++i) {
        const QChar c = text.at(i);
        if (c == QLatin1Char('\\') && i + 1 < text.size()) {
            const QChar n = text.at(++i);
            if (n == QLatin1Char('r'))
                out += '\r';
            else if (n == QLatin1Char('n'))
                out += '\n';
            else if (n == QLatin1Char('t'))
                out += '\t';
            else
                out += n.toLatin1();
        } else if (c == QLatin1Char('<') && i + 4 < text.size() &&
                   text.at(i + 1).toLower() == QLatin1Char('x') &&
                   text.at(i + 4) == QLatin1Char('>')) {
            bool ok = false;
            const int value = text.mid(i + 2, 2).toInt(&ok, 16);
            if (!ok) {
                if (error)
                    *error = QCoreApplication::translate("stepdeck::ModelPresentation",
                                                         "bad hex escape at column %1")
                                 .arg(i + 1);
                return false;
            }
            out += char(value);
            i += 4;
        } else if (c.unicode() < 0x80) {
            out += c.toLatin1();
        } else {
            if (error)
                *error = QCoreApplication::translate("stepdeck::ModelPresentation",
                                                     "non-ASCII character at column %1")
                             .arg(i + 1);
            return false;
        }
    }
    *bytes = out;
    return true;
}

} // namespace stepdeck
