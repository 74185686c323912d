#pragma once
#include "ElabCodec.h"
#include "ElabCtlMotion.h"
#include "ElabCtlParameters.h"
#include "ElabCtlStatusMapper.h"
#include "ElabCtlStream.h"
#include "ElabExchangeQueue.h"
#include "controller/Controller.h"
#include "controller/StatusPoller.h"

namespace stepdeck::elab {

// The E-LAB 3-axis adapter (manual: elab-3axis-stepper-controller.de.txt) over a Transport.
// Line discipline (one exchange in flight, timeouts, resync, overtaking) is ElabExchangeQueue;
// status words are mapped by ElabCtlStatusMapper; motion bookkeeping is ElabCtlMotion; the
// <DC2> stream is ElabCtlStream; parameter writes are planned by ElabCtlParameters.
//
// Decisions where the manual leaves room (see also docs):
// - Standstill before a move, feed, reference, first velocity move or first jog: a pre-flight
//   reads RequestAxeState and RequestMachineState and refuses at once ("axes still moving")
//   instead of waiting: callers that want to wait (the CLI) poll the status themselves.
// - feed() with one axis uses <RS> + SetFeedSteps X/Y/Z; with several axes it becomes a <DC2>
//   stream of a straight line (the single-axis feed commands cannot run a line together).
// - readParameters(): the board cannot read back; it returns the values this session last
//   wrote (said so in the message) or fails Unsupported for any never written.
// - writeParameters(verify=true) succeeds on ACK and says it could not verify.
// - After the host's panic, status.panic stays set (and jog is refused) until a move, feed,
//   reference or velocity move is accepted, or after reset/reconnect.
// - Moves finish on ACK; completion, limit hits and position corrections come from polls.
class ElabController : public Controller
{
    Q_OBJECT
public:
    ElabController(Transport* transport, const ControllerOptions& options,
                   QObject* parent = nullptr);
    ~ElabController() override;

    QString modelId() const override { return QStringLiteral("elab"); }
    Capabilities capabilities() const override;
    ParameterSchema schema() const override;

    void openLink(RequestId id) override;
    void closeLink() override;
    void readParameters(RequestId id, const QStringList& names) override;
    void writeParameters(RequestId id, const ParameterSet& values, bool verify) override;
    void moveRelative(RequestId id, const AxisVector& steps) override;
    void feed(RequestId id, const AxisVector& steps) override;
    void feedStream(RequestId id, const QVector<AxisVector>& steps) override;
    void reference(RequestId id, const QMap<Axis, int>& directions) override;
    void velocityMove(RequestId id, const AxisVector& stepsPerS) override;
    void stop(RequestId id) override;
    void panic(RequestId id) override;
    void reset(RequestId id) override;
    void setSpindle(RequestId id, int rpm) override;
    void setCoolant(RequestId id, bool on) override;
    void setDrivePower(RequestId id, int percent) override;
    void refreshStatus(RequestId id) override;
    void sendRaw(RequestId id, const QByteArray& bytes) override;
    void setPollInterval(int ms) override;

    // Observation for tests and the bench.
    const ElabExchangeQueue& exchangeQueue() const { return m_queue; }
    const StatusPoller& poller() const { return m_poller; }

protected:
    void applyJogVelocity(const AxisVelocities& stepsPerS) override;
    QString jogRefusal() const override;

private:
    using ErrorFn = std::function<void(ErrorKind, const QString&)>;
    struct Op
    {
        RequestId id = 0;
        quint64 epoch = 0; // stop, panic, reset and link loss start a new epoch
    };
    struct StatusRead
    {
        bool poll = false;
        bool continuation = false; // runs ahead of queued work (next step of a sequence)
        bool tolerant = false;     // skip stray replies (after panic)
        bool temperature = false;
        bool startButton = false;
    };

    // ---- sequences (ElabController.cpp) ----
    ElabExchange exchange(RequestId owner, const QByteArray& frame, Expect expect) const;
    void chain(QList<ElabExchange> steps, bool continuation, std::function<void()> done,
               ErrorFn failed);
    void readStatus(RequestId owner, StatusRead how, std::function<void()> done, ErrorFn failed);
    void sendCommand(const Op& op, const QByteArray& frame, std::function<void()> onAck,
                     bool continuation = true);
    void failWithNak(const Op& op, const QByteArray& frame);
    void preflight(RequestId id, ElabCtlStatusMapper::Rule rule, std::function<void(Op)> then);
    bool stale(const Op& op);
    bool requireLink(RequestId id);
    void afterStatusRead();
    void writeStep(const Op& op, const QList<ElabParameterWrite>& plan, int index,
                   const QString& note);

    // ---- link (ElabController.cpp) ----
    void onOpened();
    void linkDown(const QString& reason, bool closeTransport);
    void startPoll();
    void cancelEverything(ErrorKind kind, const QString& message);

    // ---- motion (ElabCtlMotionOps.cpp) ----
    void motionAccepted(ElabCtlMotion::Kind kind, const AxisVector& values);
    void startStream(RequestId id, const QVector<AxisVector>& steps, const Triple<qint64>& line);
    void pumpStream();
    void abortStream(ErrorKind kind, const QString& message);
    void sendJog(bool continuation);
    void correctPositions(const AxisVector& stopped);
    QString checkAxes(const AxisVector& values, qint64 minimum, qint64 maximum,
                      const QString& what) const;

    ElabExchangeQueue m_queue;
    StatusPoller m_poller{this};
    ElabCtlMotion m_motion;
    ElabCtlStream m_stream;
    ParameterSet m_written; // the values this session last wrote (the board cannot read back)
    quint16 m_machineWord = 0;
    quint8 m_axeWord = 0;
    bool m_hostPanic = false;
    quint64 m_epoch = 1;
    quint64 m_pollCount = 0;
    RequestId m_openId = 0;
    // Jog: the newest ramp output; one DC4 queued at most, built when it is written.
    Triple<qint16> m_jogRates{};
    Triple<qint16> m_jogSent{};
    bool m_jogQueued = false;
    bool m_jogMode = false;
};

} // namespace stepdeck::elab
