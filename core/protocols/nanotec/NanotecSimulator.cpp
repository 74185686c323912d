#include "NanotecSimulator.h"
#include "Logging.h"
#include "NanotecModel.h"

namespace stepdeck::nanotec {

NanotecSimulator::NanotecSimulator(const SimulatorOptions& options, QObject* parent)
    : Simulator(options, parent)
{
    QList<int> addresses = options.addresses.isEmpty() ? QList<int>{1, 2, 3} : options.addresses;
    for (int address : addresses)
        addDrive(address);
    m_timer.setTimerType(Qt::PreciseTimer);
    m_timer.setInterval(5);
    connect(&m_timer, &QTimer::timeout, this, &NanotecSimulator::tick);
    m_clock.start();
}

NanotecSimulator::~NanotecSimulator() = default;

NanotecDrive* NanotecSimulator::drive(int address) const
{
    for (const auto& d : m_drives) {
        if (d->address() == address)
            return d.get();
    }
    return nullptr;
}

NanotecDrive* NanotecSimulator::addDrive(int address)
{
    if (!isValidAddress(address) || drive(address))
        return nullptr;
    m_drives.push_back(std::make_unique<NanotecDrive>(address));
    return m_drives.back().get();
}

QList<NanotecDrive*> NanotecSimulator::drives() const
{
    QList<NanotecDrive*> out;
    for (const auto& d : m_drives)
        out << d.get();
    return out;
}

void NanotecSimulator::powerCycle(int address, int bootMs)
{
    for (auto& d : m_drives) {
        if (d->address() != address)
            continue;
        d = std::make_unique<NanotecDrive>(address);
        d->faults.silent = true;
        QTimer::singleShot(bootMs, this, [this, address] { setDriveSilent(address, false); });
        return;
    }
}

void NanotecSimulator::setDriveSilent(int address, bool silent)
{
    if (NanotecDrive* d = drive(address))
        d->faults.silent = silent;
}

void NanotecSimulator::garbleReplies(int address, int count)
{
    if (NanotecDrive* d = drive(address))
        d->faults.garble = count;
}

void NanotecSimulator::replyFromWrongAddress(int address, int count, int wrongAddress)
{
    if (NanotecDrive* d = drive(address)) {
        d->faults.wrongAddress = count;
        d->faults.wrongAddressValue = wrongAddress;
    }
}

void NanotecSimulator::flipSwitchInputInReplies(int address, int count)
{
    if (NanotecDrive* d = drive(address))
        d->faults.switchInputNoise = count;
}

void NanotecSimulator::setEncoderConnected(int address, bool connected)
{
    if (NanotecDrive* d = drive(address))
        d->setEncoderConnected(connected);
}

void NanotecSimulator::setCalibrationMs(int ms)
{
    for (const auto& d : m_drives)
        d->setCalibrationMs(ms);
}

void NanotecSimulator::ignoreSetting(int address, char command)
{
    if (NanotecDrive* d = drive(address); d && !d->faults.ignoredSettings.contains(command))
        d->faults.ignoredSettings += command;
}

void NanotecSimulator::receive(const QByteArray& bytes)
{
    for (const Command& c : m_decoder.feed(bytes)) {
        if (!c.valid) {
            qCDebug(lcSimulator) << "nanotec: dropped frame" << c.raw << c.error;
            continue; // 1.1: a drive only reacts to complete, addressed frames
        }
        noteReceived(c.raw);
        execute(c);
    }
    ensureTicking();
}

void NanotecSimulator::execute(const Command& command)
{
    if (!command.broadcast) {
        NanotecDrive* d = drive(command.address);
        if (!d || d->faults.silent)
            return;
        const int address = d->address(); // 'm' moves the drive only after its echo
        const bool wasReady = d->ready();
        const qint64 before = d->position();
        reply(d, address, d->handle(command.body));
        // 6.6: p1 travels 's' in direction 'd', p2 to position 's' (mode '!' 1: positioning).
        const qint64 p = d->value('p');
        if (command.body == "A" && wasReady && !d->ready() && d->value('!') == 1 &&
            (p == 1 || p == 2)) {
            const qint64 s = d->value('s');
            m_startedMoves.append({address, p == 1 ? (d->value('d') ? s : -s) : s - before,
                                   d->value('o'), m_clock.nsecsElapsed() / 1000});
        }
        return;
    }
    QList<QByteArray> frames;
    for (const auto& d : m_drives) {
        if (d->faults.silent)
            continue;
        const int address = d->address();
        const NanotecDrive::Answer a = d->handle(command.body);
        if (!a.body.isEmpty())
            frames << frame(address, a);
    }
    if (frames.size() == 1) {
        send(frames.first());
    } else if (frames.size() > 1) {
        // Everybody talks at once on the half-duplex bus: the host sees the bits ORed.
        QByteArray collision(frames.first().size(), '\0');
        for (const QByteArray& f : frames) {
            for (int i = 0; i < collision.size() && i < f.size(); ++i)
                collision[i] = char(collision.at(i) | f.at(i) | 0x80);
        }
        collision[collision.size() - 1] = '\r';
        send(collision);
    }
}

QByteArray NanotecSimulator::frame(int address, const NanotecDrive::Answer& answer) const
{
    const QByteArray addr = answer.longForm ? QByteArray::number(address)
                                            : QByteArray::number(address).rightJustified(3, '0');
    return addr + answer.body + '\r';
}

void NanotecSimulator::reply(NanotecDrive* d, int address, const NanotecDrive::Answer& answer)
{
    if (answer.body.isEmpty())
        return;
    int from = address;
    if (d->faults.wrongAddress > 0) {
        --d->faults.wrongAddress;
        from = d->faults.wrongAddressValue ? d->faults.wrongAddressValue : address + 1;
    }
    NanotecDrive::Answer sent = answer;
    if (d->faults.switchInputNoise > 0 && sent.body.startsWith("ZY")) {
        bool ok = false;
        const qint64 inputs = sent.body.mid(2).toLongLong(&ok);
        if (ok) {
            --d->faults.switchInputNoise;
            sent.body = "ZY" + QByteArray::number(inputs ^ 0x20);
        }
    }
    QByteArray bytes = frame(from, sent);
    if (d->faults.garble > 0) {
        --d->faults.garble;
        bytes[bytes.size() / 2] = char(0xB1); // a destroyed byte; the CR survives
    }
    send(bytes);
}

void NanotecSimulator::ensureTicking()
{
    bool active = false;
    for (const auto& d : m_drives)
        active = active || d->isActive();
    if (active && !m_timer.isActive()) {
        m_lastTickUs = m_clock.nsecsElapsed() / 1000;
        m_timer.start();
    } else if (!active) {
        m_timer.stop();
    }
}

bool NanotecSimulator::standingStill()
{
    tick();
    for (const auto& d : m_drives) {
        if (d->speed() != 0.0)
            return false;
    }
    return true;
}

void NanotecSimulator::tick()
{
    const qint64 now = m_clock.nsecsElapsed() / 1000;
    const double dt = qBound(0.0, (now - m_lastTickUs) / 1e6, 0.1);
    m_lastTickUs = now;
    for (const auto& d : m_drives) {
        const int address = d->address();
        const bool wasRunning = d->running();
        for (const QByteArray& body : d->advance(dt)) {
            if (!d->faults.silent && !d->answersDisabled())
                reply(d.get(), address, {body, false});
        }
        if (wasRunning && !d->running())
            noteArrival(address, now);
    }
    ensureTicking();
}

void NanotecSimulator::noteArrival(int address, qint64 us)
{
    for (qsizetype i = m_startedMoves.size() - 1; i >= 0; --i) {
        if (m_startedMoves[i].address == address) {
            if (m_startedMoves[i].arrivedUs < 0)
                m_startedMoves[i].arrivedUs = us;
            return;
        }
    }
}

bool NanotecSimulator::isMoving(Axis axis)
{
    const NanotecDrive* d = drive(probeAddress(axis));
    return d && d->isActive();
}

qint64 NanotecSimulator::position(Axis axis)
{
    const NanotecDrive* d = drive(probeAddress(axis));
    return d ? d->position() : 0;
}

QList<SimulatedMove> NanotecSimulator::acceptedMoves() const
{
    QList<SimulatedMove> out;
    for (const StartedMove& move : m_startedMoves) {
        // Every address 1..254 is an axis (probeAddress), so every move has one.
        if (const std::optional<Axis> axis = Axis::fromIndex(move.address - 1))
            out.append({*axis, move.steps});
    }
    return out;
}

void NanotecSimulator::emergencyStop()
{
    const bool silent = faults().silent;
    faults().silent = true; // nobody asked: no reply leaves the device
    receive("#*S\r");       // 6.2: every drive stops
    faults().silent = silent;
}

bool NanotecSimulator::isStopFrame(const QByteArray& frame) const
{
    return frame.startsWith('#') && frame.endsWith("S\r"); // '#1S', '#*S'
}

} // namespace stepdeck::nanotec
