#pragma once
#include "model/Axis.h"
#include "model/LineSettings.h"
#include <QElapsedTimer>
#include <QObject>
#include <QRandomGenerator>
#include <QTimer>

namespace stepdeck {

class Transport;

struct SimulatorOptions
{
    QList<int> addresses;    // bus addresses of simulated drives (multi-drive models)
    bool paceOutput = false; // release replies at the line's character rate
    LineSettings line;       // used for pacing
    quint32 seed = 1;        // for reproducible "random" faults
};

// Faults any simulator can inject per reply (one reply = one send() call).
struct SimulatorFaults
{
    int dropReplies = 0;    // the next N replies are not sent
    int corruptReplies = 0; // the next N replies have a byte flipped
    int delayMs = 0;        // every reply is held back this long
    bool silent = false;    // answers nothing at all
    int forceNak = 0;       // the next N commands answered by ACK/NAK get NAK and are not
                            // executed (honoured by the model simulators; requests unaffected)

    // Random faults per reply, drawn from a generator seeded with SimulatorOptions::seed, so
    // the same seed and the same traffic give the same faults (stepdeck-sim --drop/--corrupt).
    double dropProbability = 0;    // the reply is not sent
    double corruptProbability = 0; // one random byte of the reply is replaced by another
    double delayProbability = 0;   // the reply is held back 1..delayMaxMs
    int delayMaxMs = 0;
};

// What the injected faults did so far (for soak runs and --help-less reproduction reports).
struct SimulatorFaultCounts
{
    qint64 replies = 0; // replies that reached send()
    qint64 dropped = 0;
    qint64 corrupted = 0;
    qint64 delayed = 0;
    qint64 noiseBytes = 0;
    bool frozen = false;
};

// One positioning move a simulated device accepted, on one axis (Simulator::acceptedMoves).
struct SimulatedMove
{
    Axis axis;
    qint64 steps;
};

// The device side of a protocol (like QGroundControl's MockLink). It receives host bytes and
// transmits replies; time-based motion lives in the subclasses.
class Simulator : public QObject
{
    Q_OBJECT
public:
    explicit Simulator(const SimulatorOptions& options, QObject* parent = nullptr);
    ~Simulator() override;

    const SimulatorOptions& options() const { return m_options; }

    // Connects this simulator to the device end of a link (loopback or pseudo-terminal).
    void attach(Transport* deviceEnd);

    SimulatorFaults& faults() { return m_faults; }
    const SimulatorFaults& faults() const { return m_faults; }
    void setFaults(const SimulatorFaults& faults) { m_faults = faults; }
    void setPacing(bool enabled, const LineSettings& line);
    qint64 bytesPending() const { return m_paced.size(); }

    // Line noise: random bytes (any value) sent unasked at this mean rate, between and
    // inside replies as they happen to fall; 0 ends it. Not affected by `silent`: the line
    // is noisy whether the device talks or not.
    void setNoise(double bytesPerSecond);
    double noise() const { return m_noiseRate; }
    // A frozen peer: answers normally for `ms` from its next reply on, then nothing at all
    // (faults().silent) while the port stays open. Negative: never (and unfreezes).
    void freezeAfter(qint64 ms);
    const SimulatorFaultCounts& faultCounts() const { return m_counts; }

    // What this device received: every complete frame its codec decoded, in order (the newest
    // kReceivedLogSize). Safety tests assert on these, never only on the host's own state.
    static constexpr int kReceivedLogSize = 20000;
    QList<QByteArray> receivedFrames() const { return m_received; }
    int countReceived(const QByteArray& frame) const { return int(m_received.count(frame)); }
    void clearReceivedFrames() { m_received.clear(); }
    // ---- probes: what the simulated machine itself does (soak runs, the fault matrix,
    // tests). Every model's simulator answers them; axes are the model's (Capabilities). ----
    // True when no axis of the simulated machine moves (the device's own view).
    virtual bool standingStill() = 0;
    // True when this axis moves at the device now.
    virtual bool isMoving(Axis axis) = 0;
    // Where the axis stands by the device's own count.
    virtual qint64 position(Axis axis) = 0;
    // Positioning moves the device accepted, per axis with their length, in order: soak runs
    // compare them with the moves the host was told succeeded. Models that jog by short moves
    // (EMIS, laser axes) journal those too.
    virtual QList<SimulatedMove> acceptedMoves() const = 0;
    // Stops every axis at once, as a person at the machine would: a model whose protocol has a
    // stop takes it as if the host had sent it, the others (Capabilities::stopCommand false)
    // through the machine's emergency-stop circuit. Nothing is reported to the host.
    virtual void emergencyStop() = 0;
    // True when a frame as noteReceived() logged it is one of the manual's stop commands
    // (tests assert that the device received a stop). Models without a stop command: never.
    virtual bool isStopFrame(const QByteArray& frame) const;
    // Digital inputs that the simulated machine, not the device, drives (a part sensor, a
    // door): the numbers an operator or a test may set (stepdeck-sim --input, the window's
    // Simulator menu). None by default.
    virtual QList<int> settableInputs() const { return {}; }
    // Sets one of settableInputs() to a level; false for any other number.
    virtual bool setSettableInput(int number, bool level)
    {
        Q_UNUSED(number)
        Q_UNUSED(level)
        return false;
    }

public Q_SLOTS:
    virtual void receive(const QByteArray& bytes) = 0;

Q_SIGNALS:
    void transmit(const QByteArray& bytes);

protected:
    void noteReceived(const QByteArray& frame);
    // Sends one reply, applying injected faults and pacing.
    void send(const QByteArray& reply);
    // Sends bytes that are not a reply (flow control), with pacing but no faults.
    void sendUnsolicited(const QByteArray& bytes);

private:
    void emitPaced(const QByteArray& bytes);
    void releasePaced();
    bool chance(double probability);
    void emitNoise();

    SimulatorOptions m_options;
    SimulatorFaults m_faults;
    QList<QByteArray> m_received;
    QByteArray m_paced;
    QTimer m_paceTimer{this};
    QElapsedTimer m_paceClock;
    double m_paceCredit = 0; // characters the line may still carry
    qint64 m_lastReleaseUs = 0;

    QRandomGenerator m_faultRng; // per-reply decisions
    QRandomGenerator m_noiseRng; // noise bytes: independent of the reply traffic
    SimulatorFaultCounts m_counts;
    double m_noiseRate = 0;
    double m_noiseCredit = 0;
    QTimer m_noiseTimer{this};
    QElapsedTimer m_noiseClock;
    qint64 m_freezeAfterMs = -1;
    QTimer m_freezeTimer{this};
};

} // namespace stepdeck
