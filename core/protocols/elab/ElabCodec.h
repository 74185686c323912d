#pragma once
#include "model/Axis.h"
#include <QByteArray>
#include <QCoreApplication>
#include <QList>
#include <QString>
#include <array>

// E-LAB 3-axis stepper controller byte protocol (manual: elab-3axis-stepper-controller.de.txt).
// Pure and streaming: no I/O, no timers, bounded buffers.
namespace stepdeck::elab {

// The translation context of the codec's texts (decode errors, status bit descriptions).
class Codec
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::elab::Codec)
};

// "Steuerzeichen Tabelle und Kommando Liste": host -> controller command bytes.
namespace ctrl {
constexpr char SOH = 0x01;  // Set Spindle RPM            <SOH>XXXXXXXX#
constexpr char STX = 0x02;  // Set Drive Power            <STX>XX
constexpr char ETX = 0x03;  // Request relative Position  reply <ETX>XXXXXXXX,YYYYYYYY;ZZZZZZZZ.
constexpr char EOT = 0x04;  // Set FastMove XYZ           <EOT>XXXXXXXX,YYYYYYYY;ZZZZZZZZ.
constexpr char ENQ = 0x05;  // Request Machine State      reply <ENQ>BBBB#
constexpr char ACK = 0x06;  // reply: command accepted (as host byte: Request Absolute Position,
                            // undocumented -- never sent)
constexpr char BEL = 0x07;  // Set Panic Stop
constexpr char BS = 0x08;   // Set FastMove Z             <BS>ZZZZZZZZ.
constexpr char HT = 0x09;   // Request Axe State          reply <HT>BB#
constexpr char LF = 0x0A;   // Request Start Info         reply <ACK> pressed / <NAK> not
constexpr char VT = 0x0B;   // Set FeedSteps Z            <VT>ZZZZZZZZ.
constexpr char FF = 0x0C;   // Set FastMove XY            <FF>XXXXXXXX,YYYYYYYY;
constexpr char CR = 0x0D;   // End Of Feed
constexpr char SO = 0x0E;   // Set Limit Switch Polarity  <SO>XX,YY;ZZ.
constexpr char SI = 0x0F;   // Set Cooling ON/OFF         <SI>XX
constexpr char DLE = 0x10;  // Set Reference Switch Pol.  <DLE>XX,YY;ZZ.
constexpr char XON = 0x11;  // controller -> host flow control during a DC2 stream
constexpr char DC2 = 0x12;  // Set FeedSteps XYZ          <DC2><step byte>, no reply
constexpr char XOFF = 0x13; // host -> controller: Force Stop Move; controller -> host: XOFF
constexpr char DC4 = 0x14;  // Set Jog Speed              <DC4>XXXX,YYYY;ZZZZ. (signed)
constexpr char NAK = 0x15;  // reply: command refused
constexpr char SYN = 0x16;  // Request Synchronisation (no reply)
constexpr char ETB = 0x17;  // Request Temperature        reply <ETB>TT#
constexpr char CAN = 0x18;  // Set Velocity Move XYZ      <CAN>XXXX,YYYY;ZZZZ. (signed)
constexpr char EM = 0x19;   // Set FeedSteps X            <EM>XXXXXXXX,
constexpr char SUB = 0x1A;  // Set FeedSteps Y            <SUB>YYYYYYYY;
constexpr char ESC = 0x1B;  // Set Rampe                  <ESC>S|M|A XXXX,YYYY;ZZZZ.
constexpr char FS = 0x1C;   // Set Standard Feed Rate     <FS>XXXX,YYYY;ZZZZ.
constexpr char GS = 0x1D;   // Force Flush Buffer
constexpr char RS = 0x1E;   // Set Clear Position
constexpr char US = 0x1F;   // Set Reference Move XYZ     <US>XXXX,YYYY;ZZZZ. (-1/0/+1)
} // namespace ctrl

// RequestMachineState bits (Word, 16 bits).
namespace machine {
constexpr quint16 DriveOn = 1u << 0;
constexpr quint16 SpindleOn = 1u << 1;
constexpr quint16 Busy = 1u << 2;
constexpr quint16 ComFail = 1u << 3;   // not implemented by the firmware
constexpr quint16 TimeOut = 1u << 4;   // not implemented by the firmware
constexpr quint16 ParmError = 1u << 5; // not implemented by the firmware
constexpr quint16 OverTemp = 1u << 6;  // internal temperature above 50 degC
constexpr quint16 InvSetup = 1u << 7;  // StartSpeed, MaxSpeed, Acceleration not all set
constexpr quint16 LimSwX = 1u << 8;
constexpr quint16 LimSwY = 1u << 9;
constexpr quint16 LimSwZ = 1u << 10;
constexpr quint16 RefSwX = 1u << 11;
constexpr quint16 RefSwY = 1u << 12;
constexpr quint16 RefSwZ = 1u << 13;
constexpr quint16 PanicStop = 1u << 14;
} // namespace machine

// RequestAxeState bits (Byte).
namespace axe {
constexpr quint8 XMove = 1u << 0;
constexpr quint8 XJog = 1u << 1;
constexpr quint8 YMove = 1u << 2;
constexpr quint8 YJog = 1u << 3;
constexpr quint8 ZMove = 1u << 4;
constexpr quint8 ZJog = 1u << 5;
constexpr quint8 LimSw = 1u << 6;
constexpr quint8 RefSw = 1u << 7;
} // namespace axe

// The manual's bit names with plain words, for NAK reasons, tooltips and the status panel.
struct BitName
{
    int bit;
    const char* name;        // "tmDriveOn"
    const char* description; // "drives are powered"
};
const QList<BitName>& machineStateBits();
const QList<BitName>& axeStateBits();
// "tmInvSetup (setup incomplete), tmLimSwX (limit switch X active)"; "none" when no bit set.
QString describeMachineState(quint16 word);
QString describeAxeState(quint8 byte);

enum class RampKind : char { StartSpeed = 'S', MaxSpeed = 'M', Acceleration = 'A' };

template <typename T> using Triple = std::array<T, 3>; // X, Y, Z

// The board's axes and where each stands on the wire (issue 32: a table, not the axis' value):
// its place in the X;Y;Z triples of commands and replies, and its status bits by the manual's
// names (RequestAxeState taXMove .. taZJog, RequestMachineState tmLimSwX .. tmRefSwZ).
struct WireAxis
{
    Axis axis;
    std::size_t index; // in a Triple
    quint8 moveBit;
    quint8 jogBit;
    quint16 limitSwitchBit;
    quint16 referenceSwitchBit;
};
const QList<Axis>& boardAxes(); // X, Y, Z
// The board's axis (a programming error for another: it has no place on the wire).
const WireAxis& wireAxis(Axis axis);
inline std::size_t wireIndex(Axis axis)
{
    return wireAxis(axis).index;
}

// DC2 step byte: bit7 0, StepZ, StepY, StepX, bit3 0, DirZ, DirY, DirX (Dir set = negative).
quint8 encodeStepByte(int dx, int dy, int dz); // each -1, 0, +1
Triple<int> decodeStepByte(quint8 byte);
bool isValidStepByte(quint8 byte); // bits 7 and 3 clear

// ---- host -> controller encoders (upper-case hex, no spaces; manual section per command) ----
namespace encode {
QByteArray requestMachineState();                                   // <ENQ>
QByteArray requestAxeState();                                       // <HT>
QByteArray requestTemperature();                                    // <ETB>
QByteArray requestRelPosition();                                    // <ETX>
QByteArray requestStart();                                          // <LF>
QByteArray requestSync(int count);                                  // <SYN> x count
QByteArray panicStop();                                             // <BEL>
QByteArray stopMove();                                              // <XOFF>
QByteArray flushBuffer();                                           // <GS>
QByteArray clearPosition();                                         // <RS>
QByteArray endOfFeed();                                             // <CR>
QByteArray limitSwitchPolarity(const Triple<bool>& activeHigh);     // <SO>FF,FF;00.
QByteArray referenceSwitchPolarity(const Triple<bool>& activeHigh); // <DLE>FF,FF;FF.
QByteArray ramp(RampKind kind, const Triple<quint16>& values);      // <ESC>S0064,0064;0064.
QByteArray feedSpeed(const Triple<quint16>& stepsPerS);             // <FS>0064,0064;0064.
QByteArray drivePower(quint8 percent);                              // <STX>64
QByteArray spindleRpm(quint32 rpm);                                 // <SOH>000003E8#
QByteArray coolant(bool on);                                        // <SI>FF / <SI>00
QByteArray fastMoveXY(qint32 x, qint32 y);                          // <FF>000003E8,FFFFFC18;
QByteArray fastMoveXYZ(const Triple<qint32>& steps);                // <EOT>...,...;....
QByteArray fastMoveZ(qint32 z);                                     // <BS>000003E8.
QByteArray feedStepsX(qint32 x);                                    // <EM>000003E8,
QByteArray feedStepsY(qint32 y);                                    // <SUB>000003E8;
QByteArray feedStepsZ(qint32 z);                                    // <VT>000003E8.
QByteArray feedStep(quint8 stepByte);                               // <DC2>b
QByteArray jogSpeed(const Triple<qint16>& stepsPerS);               // <DC4>0064,0064;FF9C.
QByteArray referenceMove(const Triple<qint16>& directions);         // <US>FFFF,0000;0001.
QByteArray velocityMove(const Triple<qint16>& stepsPerS);           // <CAN>FC18,0000;03E9.
} // namespace encode

// ---- controller -> host encoders ("Allgemeine Befehle"; the simulator's replies) ----
namespace encodeReply {
QByteArray machineState(quint16 word);                   // <ENQ>0080#
QByteArray axeState(quint8 byte);                        // <HT>05#
QByteArray temperature(quint8 celsius);                  // <ETB>19#
QByteArray relPosition(const Triple<qint32>& remaining); // <ETX>00000000,FFFFFF9C;00000000.
} // namespace encodeReply

// ---- controller -> host replies ----
struct Reply
{
    enum class Kind {
        Ack,
        Nak,
        XOn,
        XOff,
        MachineState, // word
        AxeState,     // byte
        Temperature,  // degrees Celsius
        RelPosition,  // positions
        Invalid,      // garbage or a malformed frame: raw holds the dropped bytes
    };
    Kind kind = Kind::Invalid;
    quint16 machineState = 0;
    quint8 axeState = 0;
    quint8 temperature = 0;
    Triple<qint32> positions{};
    QByteArray raw; // the bytes of this frame as received
    QString error;  // for Invalid: why
};

// Replies are self-delimiting, so the decoder needs no knowledge of the request. Any control
// byte starts a new frame; a frame interrupted or malformed is reported as Invalid and
// decoding resynchronises at the next control byte. Never holds more than one frame.
class ReplyDecoder
{
public:
    static constexpr int kMaxFrame = 28; // <ETX>XXXXXXXX,YYYYYYYY;ZZZZZZZZ. (1 + 27 bytes)
    QList<Reply> feed(const QByteArray& bytes);
    void reset()
    {
        m_buffer.clear();
        m_discarding = false;
    }
    int buffered() const { return int(m_buffer.size()); }

private:
    QList<Reply> m_out;
    QByteArray m_buffer;
    bool m_discarding = false; // dropping bytes up to the next control byte
    QString m_discardReason;
    void flushInvalid(const QString& why);
    void startDiscarding(const QString& why);
    void completeIfDone();
};

// ---- host -> controller, decoded on the device side (simulator, traffic console) ----
struct Command
{
    char code = 0;                        // ctrl::...
    RampKind ramp = RampKind::StartSpeed; // for ESC
    int valueCount = 0;                   // values parsed
    std::array<qint64, 3> values{};       // decoded with the command's width and signedness
    quint8 stepByte = 0;                  // for DC2
    bool valid = true; // false: malformed (the device answers NAK where it answers)
    QString error;
    QByteArray raw;
};

class CommandDecoder
{
public:
    static constexpr int kMaxFrame = 28;
    QList<Command> feed(const QByteArray& bytes);
    void reset();
    int buffered() const { return int(m_buffer.size()); }
    // Bytes consumed that no command's raw carries: the blanks tolerated inside parameters.
    // Every byte fed is in a raw, in buffered() or counted here.
    qint64 unframedBytes() const { return m_unframed; }

private:
    QList<Command> m_out;
    QByteArray m_buffer;
    qint64 m_unframed = 0;
    bool m_expectStepByte = false; // after DC2 the next byte is raw data
    void complete(bool valid, const QString& error = {});
    bool tryParse(); // true when m_buffer holds a complete frame (emitted)
};

// Human-readable notation of the traffic console: control bytes as mnemonics
// ("<ESC>S0064,0064;0064.", "<ACK>"), other printable bytes as they are, the rest as <xNN>.
QString toMnemonics(const QByteArray& bytes);
// The reverse, for the console's send line: "<ENQ>", "<DC4>0064,0064;FF9C.", "<x12>".
// Returns false and says where on an unknown mnemonic.
bool fromMnemonics(const QString& text, QByteArray* bytes, QString* error);
const char* mnemonic(quint8 controlByte); // "ACK" for 0x06; nullptr above 0x1F

} // namespace stepdeck::elab
