// Model operations (outputs, reference runs, system parameters, input programs) and the console.
#include "EmisOperations.h"
#include "EmisModel.h"
#include "EmisMotion.h"
#include "EmisMotionTracker.h"
#include "EmisParameters.h"
#include "Logging.h"
#include "model/ModelOperations.h"
#include "model/NumberParsing.h"

namespace stepdeck::emis {

namespace {
std::optional<int> numberArg(const QVariantMap& args, QLatin1String key, int minimum, int maximum)
{
    qint64 n = 0;
    if (numbers::integerFromVariant(args.value(key), &n) != NumberError::None || n < minimum ||
        n > maximum)
        return std::nullopt;
    return int(n);
}

bool printableAscii(const QString& text)
{
    for (QChar c : text) {
        if (c.unicode() < 0x20 || c.unicode() >= 0x7F)
            return false;
    }
    return true;
}
} // namespace

EmisOperations::EmisOperations(EmisHost& host, EmisExchange& exchange, EmisKnownValues& known,
                               EmisMotionTracker& tracker, EmisMotion& motion,
                               EmisParameters& parameters)
    : m_host(host), m_exchange(exchange), m_known(known), m_tracker(tracker), m_motion(motion),
      m_parameters(parameters)
{}

bool EmisOperations::run(RequestId id, const QString& name, const QVariantMap& args)
{
    if (name == operation::kSetOutput)
        setOutput(id, args);
    else if (name == operation::kReference)
        referenceOperation(id, args);
    else if (name == operation::kStoreParameters)
        m_parameters.store(id, args);
    else if (name == operation::kReadStoredParameters)
        m_parameters.readStored(id);
    else if (name == operation::kClearStoredParameters)
        m_parameters.clearStored(id);
    else if (name == operation::kWriteInputProgram)
        writeInputProgram(id, args);
    else if (name == operation::kEraseInputProgram)
        eraseInputProgram(id, args);
    else
        return false;
    return true;
}

void EmisOperations::setOutput(RequestId id, const QVariantMap& args)
{
    const auto output = numberArg(args, operation::arg::kOutput, 1, kOutputCount);
    if (!output) {
        return m_host.fail(id, ErrorKind::InvalidValue,
                           tr("output '%1' does not exist (outputs 1..%2, manual 9.3)")
                               .arg(args.value(operation::arg::kOutput).toString())
                               .arg(kOutputCount));
    }
    if (!m_host.requireLink(id))
        return;
    const bool on = args.value(operation::arg::kOn).toBool();
    const QByteArray bytes = encode::output(*output, on);
    m_exchange.request(bytes, EmisLink::Expect::Ack,
                       [this, id, bytes, output, on](const EmisLink::Result& r) {
                           if (r.outcome != EmisLink::Outcome::Ok)
                               return m_host.failExchange(id, bytes, r);
                           m_host.statusToChange().outputs[*output - 1] = on;
                           m_host.publish();
                           m_host.succeed(id);
                       });
}

void EmisOperations::referenceOperation(RequestId id, const QVariantMap& args)
{
    if (!m_host.requireLink(id))
        return;
    QList<Axis> axes;
    for (QChar c : args.value(operation::arg::kAxes).toString()) {
        const auto axis = axisFromName(QString(c));
        if (!axis) {
            return m_host.fail(id, ErrorKind::InvalidValue,
                               tr("unknown axis '%1' (this machine has X, Y, Z, U)").arg(c));
        }
        if (!axes.contains(*axis))
            axes << *axis;
    }
    if (axes.isEmpty())
        return m_host.fail(id, ErrorKind::InvalidValue, tr("name at least one axis to reference"));
    m_motion.startHome(id, axes, args.value(operation::arg::kSimultaneous).toBool());
}

QList<QByteArray> EmisOperations::programLines(const QVariantMap& args, QString* error) const
{
    QList<QByteArray> lines;
    const QStringList commands = args.value(operation::arg::kCommands).toStringList();
    for (int i = 0; i < commands.size(); ++i) {
        const QString text = commands[i].trimmed();
        const QString why = printableAscii(text) ? QString(validateProgramLine(text.toLatin1()))
                                                 : tr("not printable ASCII");
        if (!why.isEmpty()) {
            *error = tr("program command %1 ('%2'): %3").arg(i + 1).arg(text, why);
            return {};
        }
        lines << text.toLatin1();
    }
    if (lines.isEmpty())
        *error = tr("a program needs at least one command");
    return lines;
}

void EmisOperations::writeInputProgram(RequestId id, const QVariantMap& args)
{
    const auto input = numberArg(args, operation::arg::kInput, 1, kInputCount);
    if (!input) {
        return m_host.fail(id, ErrorKind::InvalidValue,
                           tr("input '%1' does not exist (inputs 1..%2)")
                               .arg(args.value(operation::arg::kInput).toString())
                               .arg(kInputCount));
    }
    const QString title = args.value(operation::arg::kTitle).toString();
    if (!printableAscii(title) || title.size() > limits::kTitleMax) {
        return m_host.fail(id, ErrorKind::InvalidValue,
                           tr("the program title must be printable ASCII of at most %1 characters "
                              "(no umlauts)")
                               .arg(limits::kTitleMax));
    }
    QString error;
    const QList<QByteArray> lines = programLines(args, &error);
    if (lines.isEmpty())
        return m_host.fail(id, ErrorKind::InvalidValue, error);
    if (*input <= 4 && !args.value(operation::arg::kForce).toBool()) {
        return m_host.fail(id, ErrorKind::Refused,
                           tr("input %1 carries the reference switch of axis %2: a program on it "
                              "can make the controller misbehave (manual 5.2.2); force it only "
                              "if no switch is wired there")
                               .arg(*input)
                               .arg(axisName(*axisOfNumber(*input))));
    }
    if (!m_host.requireLink(id))
        return;
    if (m_tracker.anyAwaiting() || m_host.jogInputActive() || m_exchange.inputProgramOpen()) {
        return m_host.fail(id, ErrorKind::Refused,
                           tr("input programs are written while every axis stands still"));
    }
    // 9.17: *PWINn, the header closed by <STX>, each command with <CR>, <ETX>. Nothing else may
    // reach the board in between (a poll would become part of the program).
    QList<QByteArray> frames{encode::programOpen(*input),
                             encode::programHeader(*input, title.toLatin1())};
    for (const QByteArray& line : lines)
        frames << encode::programLine(line);
    frames << encode::programEnd();
    m_exchange.link().setExclusive(true); // inputProgramOpen() from here
    programStep(id, *input, frames, 0);
}

void EmisOperations::programStep(RequestId id, int input, const QList<QByteArray>& frames,
                                 int index)
{
    if (index >= frames.size()) {
        m_exchange.link().setExclusive(false);
        return m_host.succeed(id);
    }
    m_exchange.request(
        frames[index], EmisLink::Expect::Ack,
        [this, id, input, frames, index](const EmisLink::Result& r) {
            if (r.outcome == EmisLink::Outcome::Ok)
                return programStep(id, input, frames, index + 1);
            const QString why = m_exchange.failureText(frames[index], r);
            if (index == 0 || r.outcome == EmisLink::Outcome::Cancelled) {
                m_exchange.link().setExclusive(false);
                return m_host.fail(id, m_exchange.failureKind(r), why);
            }
            abortProgram(id, input, why, m_exchange.failureKind(r));
        },
        EmisParameters::kStoreTimeoutMs, 0, true);
}

void EmisOperations::abortProgram(RequestId id, int input, const QString& why, ErrorKind kind)
{
    // The board is in programming mode: <ETX> ends it, *PEINn erases what it took so far.
    m_exchange.request(
        encode::programEnd(), EmisLink::Expect::Ack,
        [this, id, input, why, kind](const EmisLink::Result&) {
            m_exchange.link().setExclusive(false);
            m_exchange.request(
                encode::programErase(input), EmisLink::Expect::Ack,
                [this, id, input, why, kind](const EmisLink::Result& erased) {
                    const QString what =
                        erased.outcome == EmisLink::Outcome::Ok
                            ? tr("the partial program was erased (*PEIN%1)").arg(input)
                            : tr("erasing the partial program (*PEIN%1) failed too: check "
                                 "the input before using it")
                                  .arg(input);
                    m_host.fail(
                        id, kind,
                        tr("program for input %1 not stored: %2; %3").arg(input).arg(why, what));
                },
                EmisParameters::kStoreTimeoutMs);
        },
        EmisParameters::kStoreTimeoutMs, 0, true);
}

void EmisOperations::eraseInputProgram(RequestId id, const QVariantMap& args)
{
    const auto input = numberArg(args, operation::arg::kInput, 1, kInputCount);
    if (!input) {
        return m_host.fail(id, ErrorKind::InvalidValue,
                           tr("input '%1' does not exist (inputs 1..%2)")
                               .arg(args.value(operation::arg::kInput).toString())
                               .arg(kInputCount));
    }
    if (!m_host.requireLink(id))
        return;
    const QByteArray bytes = encode::programErase(*input);
    m_exchange.request(
        bytes, EmisLink::Expect::Ack,
        [this, id, bytes](const EmisLink::Result& r) {
            if (r.outcome != EmisLink::Outcome::Ok)
                return m_host.failExchange(id, bytes, r);
            m_host.succeed(id);
        },
        EmisParameters::kStoreTimeoutMs);
}

void EmisOperations::sendRaw(RequestId id, const QByteArray& bytes)
{
    if (!m_host.requireLink(id))
        return;
    CommandDecoder decoder;
    const QList<CommandDecoder::Frame> frames = decoder.feed(bytes);
    if (frames.size() != 1 || frames.first().overlong) {
        return m_host.fail(id, ErrorKind::InvalidValue,
                           tr("the console sends one SMC-IC4 command at a time"));
    }
    const Command c = parseCommand(frames.first().text, frames.first().terminator);
    if (c.kind == Command::Kind::Invalid)
        return m_host.fail(id, ErrorKind::InvalidValue, c.error);
    if (const QString e = rangeError(c); !e.isEmpty())
        return m_host.fail(id, ErrorKind::InvalidValue, e);
    switch (c.kind) {
    case Command::Kind::Vector: // through the bookkeeping, so positions stay right
        // Each target as typed: "L1,X100,y50" moves X to 100 and Y by 50 (9.11).
        if (const QString refusal = m_motion.unknownAbsolute(c.targets); !refusal.isEmpty())
            return m_host.fail(id, ErrorKind::Refused, refusal);
        return m_motion.startVector(id, c.targets, false);
    case Command::Kind::Home:
        return m_motion.startHome(id, c.axes, c.simultaneous);
    case Command::Kind::ProgramOpen:
    case Command::Kind::ProgramHeader:
    case Command::Kind::ProgramEnd:
        return m_host.fail(id, ErrorKind::Refused,
                           tr("input programs are written with the program editor, not the "
                              "console"));
    default:
        break;
    }
    sendConsoleCommand(id, frames.first().text + frames.first().terminator, c);
}

void EmisOperations::sendConsoleCommand(RequestId id, const QByteArray& frame, const Command& c)
{
    const bool stored = c.kind == Command::Kind::SystemWrite;
    m_exchange.request(
        frame, stored ? EmisLink::Expect::Stored : EmisLink::Expect::Ack,
        [this, id, frame, c](const EmisLink::Result& r) {
            if (r.outcome != EmisLink::Outcome::Ok)
                return m_host.failExchange(id, frame, r);
            if (c.kind == Command::Kind::SystemWrite) {
                m_parameters.noteStoredEntry(c.system);
            } else if (c.kind == Command::Kind::ReadSystem) {
                m_parameters.noteStored(parseSystemParameters(r.text));
            } else if (c.kind == Command::Kind::Output) {
                m_host.statusToChange().outputs[c.number - 1] = c.on;
            } else if (c.kind == Command::Kind::Ramp) {
                m_known.ramp = c.value;
            } else if (c.kind == Command::Kind::StartSpeed) {
                for (Axis a : c.axis ? QList<Axis>{*c.axis} : emisAxes())
                    m_known.startSpeed.insert(a, c.value);
            } else if (c.kind == Command::Kind::WorkSpeed) {
                for (Axis a : c.axis ? QList<Axis>{*c.axis} : emisAxes())
                    m_known.speeds.setWritten(a, c.value);
            }
            m_host.publish();
            m_host.succeed(id, QString::fromLatin1(r.text));
        },
        stored ? EmisParameters::kStoreTimeoutMs : 0, stored ? c.system.motorCount() : 0);
}

} // namespace stepdeck::emis
