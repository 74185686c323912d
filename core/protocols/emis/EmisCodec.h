#pragma once
#include "model/Axis.h"
#include <QByteArray>
#include <QCoreApplication>
#include <QList>
#include <QString>
#include <optional>

// EMIS SMC-IC4 ASCII protocol (manual: emis-smc-ic4-manual.de.txt, chapter 9). Pure and
// streaming: no I/O, no timers, bounded buffers. The command grammar (device side, program
// validation, console) is in EmisGrammar.h.
namespace stepdeck::emis {

// ---- control characters (chapter 9 introduction, 9.17) ----
constexpr char kCr = '\r';
constexpr char kStx = 0x02; // ends the header of an input program (9.17)
constexpr char kEtx = 0x03; // ends the programming of an input (9.17)
constexpr char kAck = 0x06;
constexpr char kBel = 0x07; // the board refuses (invalid value, axis busy)
constexpr char kNak = 0x15; // a move started (9.9, 9.11)
constexpr char kDc1 = 0x11; // DC1..DC4: axis X..U arrived (9.9, 9.11)

constexpr int kInputCount = 8; // 5.2: inputs 1..8, 1..4 carry the reference switches
// 9.14: the <ACK>s after "Ready!" of a "##" write. Every example shows four, also "##R,100"
// and "##S,200,1800,100"; the text ("entsprechend der Anzahl von eingetragenen
// Systemparametern") could mean fewer for an entry naming fewer motors. StepDeck reads every
// entry the same way: four, or at least one per motor it names followed by a quiet line
// (EmisLink::Expect::Stored).
constexpr int kStoredAcks = 4;
constexpr int kOutputCount = 7; // 5.3: outputs 1..7

// 'x', 'y', 'z', 'u' as in every per-axis command of chapter 9.
// The controller's own axes (issue 32: its list, not the application's): each with its letter
// and its number 1..4 (<DC1>..<DC4> arrivals, IN1..IN4 reference inputs).
struct WireAxis
{
    Axis axis;
    char letter; // lower case, as in "$Hxyzu"
    int number;
};
const QList<Axis>& emisAxes();           // X, Y, Z, U
int axisNumber(Axis axis);               // 1..4 (a programming error for another axis)
std::optional<Axis> axisOfNumber(int n); // 1..4, else none
char axisLetter(Axis axis);
std::optional<Axis> axisFromLetter(char letter); // either case
// <DC1>..<DC4> for X..U (9.9: "<DC2>, <DC3>, <DC4> bei Y-, Z- und U-Motor").
char arrivalCode(Axis axis);

// One target of a vector move (9.11): lower-case axis letter = relative steps, upper case =
// absolute position.
struct VectorTarget
{
    Axis axis = Axis::X;
    qint64 value = 0;
    bool absolute = false;
};

// ---- host -> board ----
namespace encode {
QByteArray version();                                                 // "@V\r" (9.1)
QByteArray input(int number);                                         // "@I1\r" (9.2), 1..8
QByteArray allInputs();                                               // "@IG\r" (9.2)
QByteArray output(int number, bool on);                               // "A1,1\r" / "A1,0\r" (9.3)
QByteArray startSpeedAll(qint64 stepsPerS);                           // "#S200\r" (9.4)
QByteArray startSpeed(Axis axis, qint64 stepsPerS);                   // "#S,x200\r" (9.4)
QByteArray workSpeedAll(qint64 stepsPerS);                            // "#E1,1000\r" (9.5)
QByteArray workSpeed(Axis axis, qint64 stepsPerS);                    // "#E1,x1000\r" (9.5)
QByteArray referenceSpeed(qint64 stepsPerS);                          // "#E9,400\r" (9.5)
QByteArray ramp(qint64 ms);                                           // "#R100\r" (9.6)
QByteArray stepResolution(Axis axis, qint64 microsteps);              // "D,x32\r" (9.7)
QByteArray current(Axis axis, qint64 runPercent, qint64 idlePercent); // "c,x100,20\r" (9.8)
// "$Hxy\r" (9.9), the axes in X,Y,Z,U order; simultaneous: "$Hxy,a\r".
QByteArray home(const QList<Axis>& axes, bool simultaneous);
QByteArray referenceOffset(Axis axis, qint64 steps);   // "#Ox,10\r" (9.10)
QByteArray vector(const QList<VectorTarget>& targets); // "L1,x1000,y-2000\r", "L1,X1000\r" (9.11)
QByteArray interpolation(bool on);                     // "IP1\r" / "IP0\r" (9.12)
QByteArray wait(qint64 ms);                            // "W500\r" (9.13)

// System parameters (9.14), one value per axis in X,Y,Z,U order:
// key "D" -> "##D,x32,y16,z64,u1\r", "S" -> "##S,x200,...", "E" -> "##E,x1800,...",
// "E9" -> "##E9,x400,...".
QByteArray systemPerAxis(const QByteArray& key, const QMap<Axis, qint64>& values);
// "##c,x100,0,y100,0,z100,20,u100,0\r": run and idle current per axis.
QByteArray systemCurrents(const QMap<Axis, QPair<qint64, qint64>>& runIdle);
// "##REFSW,xNO,yNO,zNO,uNC\r": true = normally closed (Öffner).
QByteArray systemReferenceSwitches(const QMap<Axis, bool>& normallyClosed);
QByteArray systemRamp(qint64 ms); // "##R,100\r"
QByteArray readSystem();          // "*PRSYS\r" (9.15)
QByteArray clearSystem();         // "*PESYS\r" (9.16)

// Input programs (9.17 / 9.18).
QByteArray programOpen(int input);                            // "*PWIN7\r"
QByteArray programHeader(int input, const QByteArray& title); // "IJ7,1 <title><STX>"
QByteArray programLine(const QByteArray& command);            // "<command>\r"
QByteArray programEnd();                                      // "<ETX>"
QByteArray programErase(int input);                           // "*PEIN1\r"
} // namespace encode

// ---- board -> host ----
// The manual prints replies both with an echo of the command and blanks ("$Hx<NAK><DC1>",
// "<NAK> <DC1>", "*PESYS <ACK>", "<ACK> Ready! <ACK> <ACK>"): replies are read as optional
// text closed by one terminator byte.
struct Event
{
    enum class Kind {
        Ack,     // <ACK> closes `text` (may be empty, an echo, an answer or "Ready!")
        Nak,     // <NAK>: a move or reference run started (text: an echo, if any)
        Bell,    // <BEL>: the board refused the command (text: an echo, if any)
        Arrived, // <DCn>: axis `axis` arrived; never consumes text (it may arrive mid-answer)
        Invalid, // garbage (bytes that are neither ASCII text nor a terminator) or an overlong
                 // text: `raw` holds the dropped bytes, `error` says why
    };
    Kind kind = Kind::Invalid;
    QByteArray text; // leading/trailing blanks, CR and LF removed
    Axis axis = Axis::X;
    QByteArray raw;
    QString error;
};

// Frames by terminator bytes only (never by silence). A <DCn> between the bytes of an answer
// is reported on its own and the answer continues. Garbage drops the text gathered so far
// (reported as Invalid) and decoding starts afresh behind it. Never holds more than kMaxText
// bytes: an overlong text is reported and dropped up to and including its terminator.
class ReplyDecoder
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::emis::ReplyDecoder)

public:
    static constexpr int kMaxText = 1024; // *PRSYS lists every stored entry (~200 bytes)
    QList<Event> feed(const QByteArray& bytes);
    void reset();
    int buffered() const { return int(m_text.size() + m_garbage.size()); }
    // Bytes consumed without appearing in an event: blanks around a text, and the tail and
    // terminator of an overlong text. Every fed byte is in an event's text or raw, is a
    // terminator, is buffered or is counted here (checked by the fuzz target).
    qint64 skippedBytes() const { return m_skipped; }

private:
    void flushGarbage(QList<Event>* out);

    qint64 m_skipped = 0;
    QByteArray m_text;
    QByteArray m_garbage;
    bool m_discarding = false; // overlong text: drop until its terminator
};

// ---- answers (the text of an Ack) ----
// The text after the echo `echo` (its last occurrence), blanks trimmed; the whole text when
// it carries no echo (the manual shows both).
QByteArray payloadAfterEcho(const QByteArray& text, const QByteArray& echo);
// 9.1: "@V SMC-IC4 v1.07" -> "SMC-IC4 v1.07"; empty text -> nullopt.
std::optional<QString> parseVersion(const QByteArray& text);
// 9.2: "@IG 10000000" -> eight levels, input 1 first (input 1 is the leftmost digit).
std::optional<QList<bool>> parseAllInputs(const QByteArray& text);
// 9.2: "@I1 0" -> the level of input `number`.
std::optional<bool> parseInput(const QByteArray& text, int number);
// 9.14: the second text of a system-parameter write, "Ready!".
bool isReady(const QByteArray& text);

} // namespace stepdeck::emis
