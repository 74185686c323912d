// Model operations (outputs, reference runs, system parameters, input programs) and the console.
#include "EmisController.h"
#include "Logging.h"
#include "model/ModelOperations.h"
#include "model/NumberParsing.h"

namespace stepdeck::emis {

namespace {
std::optional<int> numberArg(const QVariantMap& args, const char* key, int minimum, int maximum)
{
    qint64 n = 0;
    if (numbers::integerFromVariant(args.value(QLatin1String(key)), &n) != NumberError::None ||
        n < minimum || n > maximum)
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

void EmisController::modelOperation(RequestId id, const QString& name, const QVariantMap& args)
{
    if (name == operation::kSetOutput)
        return setOutput(id, args);
    if (name == operation::kReference)
        return referenceOperation(id, args);
    if (name == operation::kStoreParameters)
        return storeParameters(id, args);
    if (name == operation::kReadStoredParameters)
        return readStoredParameters(id);
    if (name == operation::kClearStoredParameters)
        return clearStoredParameters(id);
    if (name == operation::kWriteInputProgram)
        return writeInputProgram(id, args);
    if (name == operation::kEraseInputProgram)
        return eraseInputProgram(id, args);
    Controller::modelOperation(id, name, args);
}

void EmisController::setOutput(RequestId id, const QVariantMap& args)
{
    const auto output = numberArg(args, "output", 1, kOutputCount);
    if (!output) {
        return finishError(id, ErrorKind::InvalidValue,
                           tr("output '%1' does not exist (outputs 1..%2, manual 9.3)")
                               .arg(args.value(QStringLiteral("output")).toString())
                               .arg(kOutputCount));
    }
    if (!requireLink(id))
        return;
    const bool on = args.value(QStringLiteral("on")).toBool();
    const QByteArray bytes = encode::output(*output, on);
    request(bytes, EmisLink::Expect::Ack, [this, id, bytes, output, on](const EmisLink::Result& r) {
        if (r.outcome != EmisLink::Outcome::Ok)
            return finishFailure(id, bytes, r);
        mutableStatus().outputs[*output - 1] = on;
        publish();
        finishOk(id);
    });
}

void EmisController::referenceOperation(RequestId id, const QVariantMap& args)
{
    if (!requireLink(id))
        return;
    QList<Axis> axes;
    for (QChar c : args.value(QStringLiteral("axes")).toString()) {
        const auto axis = axisFromName(QString(c));
        if (!axis) {
            return finishError(id, ErrorKind::InvalidValue,
                               tr("unknown axis '%1' (this machine has X, Y, Z, U)").arg(c));
        }
        if (!axes.contains(*axis))
            axes << *axis;
    }
    if (axes.isEmpty())
        return finishError(id, ErrorKind::InvalidValue, tr("name at least one axis to reference"));
    startHome(id, axes, args.value(QStringLiteral("simultaneous")).toBool());
}

void EmisController::writeInputProgram(RequestId id, const QVariantMap& args)
{
    const auto input = numberArg(args, "input", 1, kInputCount);
    if (!input) {
        return finishError(id, ErrorKind::InvalidValue,
                           tr("input '%1' does not exist (inputs 1..%2)")
                               .arg(args.value(QStringLiteral("input")).toString())
                               .arg(kInputCount));
    }
    const QString title = args.value(QStringLiteral("title")).toString();
    if (!printableAscii(title) || title.size() > limits::kTitleMax) {
        return finishError(id, ErrorKind::InvalidValue,
                           tr("the program title must be printable ASCII of at most %1 characters "
                              "(no umlauts)")
                               .arg(limits::kTitleMax));
    }
    QList<QByteArray> lines;
    const QStringList commands = args.value(QStringLiteral("commands")).toStringList();
    for (int i = 0; i < commands.size(); ++i) {
        const QString text = commands[i].trimmed();
        const QString error = printableAscii(text) ? QString(validateProgramLine(text.toLatin1()))
                                                   : tr("not printable ASCII");
        if (!error.isEmpty()) {
            return finishError(id, ErrorKind::InvalidValue,
                               tr("program command %1 ('%2'): %3").arg(i + 1).arg(text, error));
        }
        lines << text.toLatin1();
    }
    if (lines.isEmpty())
        return finishError(id, ErrorKind::InvalidValue, tr("a program needs at least one command"));
    if (*input <= 4 && !args.value(QStringLiteral("force")).toBool()) {
        return finishError(id, ErrorKind::Refused,
                           tr("input %1 carries the reference switch of axis %2: a program on it "
                              "can make the controller misbehave (manual 5.2.2); force it only "
                              "if no switch is wired there")
                               .arg(*input)
                               .arg(axisName(Axis(*input - 1))));
    }
    if (!requireLink(id))
        return;
    if (anyAwaiting() || jogActive() || m_programming) {
        return finishError(id, ErrorKind::Refused,
                           tr("input programs are written while every axis stands still"));
    }
    // 9.17: *PWINn, the header closed by <STX>, each command with <CR>, <ETX>. Nothing else may
    // reach the board in between (a poll would become part of the program).
    QList<QByteArray> frames{encode::programOpen(*input),
                             encode::programHeader(*input, title.toLatin1())};
    for (const QByteArray& line : lines)
        frames << encode::programLine(line);
    frames << encode::programEnd();
    m_programming = true;
    m_link->setExclusive(true);
    programStep(id, *input, frames, 0);
}

void EmisController::programStep(RequestId id, int input, const QList<QByteArray>& frames,
                                 int index)
{
    if (index >= frames.size()) {
        m_programming = false;
        m_link->setExclusive(false);
        return finishOk(id);
    }
    request(
        frames[index], EmisLink::Expect::Ack,
        [this, id, input, frames, index](const EmisLink::Result& r) {
            if (r.outcome == EmisLink::Outcome::Ok)
                return programStep(id, input, frames, index + 1);
            const QString why = failureText(frames[index], r);
            if (index == 0 || r.outcome == EmisLink::Outcome::Cancelled) {
                m_programming = false;
                m_link->setExclusive(false);
                return finishError(id, failureKind(r), why);
            }
            abortProgram(id, input, why, failureKind(r));
        },
        kStoreTimeoutMs, 0, true);
}

void EmisController::abortProgram(RequestId id, int input, const QString& why, ErrorKind kind)
{
    // The board is in programming mode: <ETX> ends it, *PEINn erases what it took so far.
    request(
        encode::programEnd(), EmisLink::Expect::Ack,
        [this, id, input, why, kind](const EmisLink::Result&) {
            m_programming = false;
            m_link->setExclusive(false);
            request(
                encode::programErase(input), EmisLink::Expect::Ack,
                [this, id, input, why, kind](const EmisLink::Result& erased) {
                    const QString what =
                        erased.outcome == EmisLink::Outcome::Ok
                            ? tr("the partial program was erased (*PEIN%1)").arg(input)
                            : tr("erasing the partial program (*PEIN%1) failed too: check "
                                 "the input before using it")
                                  .arg(input);
                    finishError(
                        id, kind,
                        tr("program for input %1 not stored: %2; %3").arg(input).arg(why, what));
                },
                kStoreTimeoutMs);
        },
        kStoreTimeoutMs, 0, true);
}

void EmisController::eraseInputProgram(RequestId id, const QVariantMap& args)
{
    const auto input = numberArg(args, "input", 1, kInputCount);
    if (!input) {
        return finishError(id, ErrorKind::InvalidValue,
                           tr("input '%1' does not exist (inputs 1..%2)")
                               .arg(args.value(QStringLiteral("input")).toString())
                               .arg(kInputCount));
    }
    if (!requireLink(id))
        return;
    const QByteArray bytes = encode::programErase(*input);
    request(
        bytes, EmisLink::Expect::Ack,
        [this, id, bytes](const EmisLink::Result& r) {
            if (r.outcome != EmisLink::Outcome::Ok)
                return finishFailure(id, bytes, r);
            finishOk(id);
        },
        kStoreTimeoutMs);
}

void EmisController::sendRaw(RequestId id, const QByteArray& bytes)
{
    if (!requireLink(id))
        return;
    CommandDecoder decoder;
    const QList<CommandDecoder::Frame> frames = decoder.feed(bytes);
    if (frames.size() != 1 || frames.first().overlong) {
        return finishError(id, ErrorKind::InvalidValue,
                           tr("the console sends one SMC-IC4 command at a time"));
    }
    const Command c = parseCommand(frames.first().text, frames.first().terminator);
    if (c.kind == Command::Kind::Invalid)
        return finishError(id, ErrorKind::InvalidValue, c.error);
    if (const QString e = rangeError(c); !e.isEmpty())
        return finishError(id, ErrorKind::InvalidValue, e);
    switch (c.kind) {
    case Command::Kind::Vector: // through the bookkeeping, so positions stay right
        // Each target as typed: "L1,X100,y50" moves X to 100 and Y by 50 (9.11).
        if (const QString refusal = unknownAbsolute(c.targets); !refusal.isEmpty())
            return finishError(id, ErrorKind::Refused, refusal);
        return startVector(id, c.targets, false);
    case Command::Kind::Home:
        return startHome(id, c.axes, c.simultaneous);
    case Command::Kind::ProgramOpen:
    case Command::Kind::ProgramHeader:
    case Command::Kind::ProgramEnd:
        return finishError(id, ErrorKind::Refused,
                           tr("input programs are written with the program editor, not the "
                              "console"));
    default:
        break;
    }
    const bool stored = c.kind == Command::Kind::SystemWrite;
    const QByteArray frame = frames.first().text + frames.first().terminator;
    request(
        frame, stored ? EmisLink::Expect::Stored : EmisLink::Expect::Ack,
        [this, id, frame, c](const EmisLink::Result& r) {
            if (r.outcome != EmisLink::Outcome::Ok)
                return finishFailure(id, frame, r);
            if (c.kind == Command::Kind::SystemWrite) {
                m_stored.store(c.system);
                noteStored(m_stored);
            } else if (c.kind == Command::Kind::ReadSystem) {
                noteStored(parseSystemParameters(r.text));
            } else if (c.kind == Command::Kind::Output) {
                mutableStatus().outputs[c.number - 1] = c.on;
            } else if (c.kind == Command::Kind::Ramp) {
                m_known.ramp = c.value;
            } else if (c.kind == Command::Kind::StartSpeed) {
                for (Axis a : c.axis ? QList<Axis>{*c.axis} : allAxes())
                    m_known.startSpeed.insert(a, c.value);
            } else if (c.kind == Command::Kind::WorkSpeed) {
                for (Axis a : c.axis ? QList<Axis>{*c.axis} : allAxes())
                    m_speeds.setWritten(a, c.value);
            }
            publish();
            finishOk(id, QString::fromLatin1(r.text));
        },
        stored ? kStoreTimeoutMs : 0, stored ? c.system.motorCount() : 0);
}

} // namespace stepdeck::emis
