#pragma once
#include "controller/Controller.h"
#include "model/ModelInfo.h"
#include "sim/Simulator.h"
#include <QObject>
#include <QThread>
#include <atomic>
#include <functional>

namespace stepdeck {

struct ConnectionSpec
{
    // The model is not named here: create() takes its descriptor (ModelInfo), whose id is the
    // only spelling (ControllerSession::model()->id).
    QString port; // serial device path, "tcp://HOST:PORT" or "sim" (in-process simulator)
    ControllerOptions options;
    SimulatorOptions simulator; // used for port "sim"
};

// The GUI's and CLI's handle on a controller. It runs the controller stack (transport,
// adapter, poller, jog ramp and, for "sim", the simulator) in its own thread and talks to it
// only through queued calls and signals, so the caller never blocks on I/O.
// Stop, panic and jog updates are posted with high event priority: they overtake queued work.
class ControllerSession : public QObject
{
    Q_OBJECT
public:
    // destroy() waits at most this long for the adapter's safety stop and close.
    static constexpr int kDestroyCloseWaitMs = 3000;

    explicit ControllerSession(QObject* parent = nullptr);
    ~ControllerSession() override;

    // Creates the model's stack for spec in the controller thread; model() is then model.
    // model must outlive the session (the registry's entries do). Returns false and
    // says why when the model cannot be built. The link opens with open().
    bool create(const ModelInfo& model, const ConnectionSpec& spec, QString* error);
    void destroy();
    bool isCreated() const { return m_controller != nullptr; }

    const ConnectionSpec& spec() const { return m_spec; }
    const ModelInfo* model() const { return m_model; }
    Capabilities capabilities() const;
    ParameterSchema schema() const;
    LinkState linkState() const { return m_linkState; }
    const MachineStatus& status() const { return m_status; }
    double pollRateHz() const { return m_pollRateHz; }
    bool isSimulated() const { return m_simulator != nullptr; }

    RequestId open();
    void close();
    RequestId readParameters(const QStringList& names);
    RequestId writeParameters(const ParameterSet& values, bool verify);
    RequestId moveRelative(const AxisVector& steps);
    RequestId moveAbsolute(const AxisVector& targets);
    // One short jog move of a model that jogs by targets (Capabilities::jogByTargets): a
    // relative move shortened so that it ends at the soft limit at the latest; refused with
    // the reason once every axis stands at its limit. stepsPerS: the jog rates the steps stand
    // for (published as the axes' commandedVelocity while jogging by targets).
    RequestId jogStep(const AxisVector& steps, const AxisVelocities& stepsPerS = {});
    RequestId feed(const AxisVector& steps);
    RequestId feedStream(const QVector<AxisVector>& steps);
    RequestId feedContour(std::shared_ptr<motion::ContourFeed> contour);
    RequestId reference(const QMap<Axis, int>& directions);
    RequestId velocityMove(const AxisVector& stepsPerS);
    RequestId stop();
    RequestId panic();
    RequestId reset();
    RequestId setSpindle(int rpm);
    RequestId setCoolant(bool on);
    RequestId setDrivePower(int percent);
    RequestId refreshStatus();
    RequestId sendRaw(const QByteArray& bytes);
    RequestId scanBus();
    RequestId modelOperation(const QString& name, const QVariantMap& args = {});
    void setPollInterval(int ms);
    void setJogVelocity(const AxisVelocities& targets);
    void endJog();
    void setJogAcceleration(double stepsPerS2);
    // Soft limits the controller enforces for moves and jog (see SoftLimits); kept across
    // create() so a reconnect enforces them at once.
    void setSoftLimits(const SoftLimits& limits);
    SoftLimits softLimits() const { return m_softLimits; }

    // Runs fn on the in-process simulator in the controller thread (tests, fault injection).
    void withSimulator(std::function<void(Simulator*)> fn);

Q_SIGNALS:
    void linkStateChanged(stepdeck::LinkState state, const QString& reason);
    void statusChanged(const stepdeck::MachineStatus& status);
    void requestFinished(const stepdeck::CommandResult& result);
    void errorOccurred(const QString& message);
    void traffic(const stepdeck::TrafficRecord& record);
    void pollRateChanged(double hz);
    void jogRefused(const QString& reason);

private:
    RequestId nextId() { return ++m_lastId; }
    void post(std::function<void(Controller*)> fn, bool urgent = false);
    // Posts call with a fresh request id; without a controller the id finishes as LinkDown.
    RequestId submit(std::function<void(Controller*, RequestId)> call, bool urgent = false);

    ConnectionSpec m_spec;
    const ModelInfo* m_model = nullptr;
    QThread m_thread;
    QObject* m_context = nullptr;       // lives in m_thread; owns the stack
    Controller* m_controller = nullptr; // lives in m_thread
    Simulator* m_simulator = nullptr;   // lives in m_thread
    LinkState m_linkState = LinkState::Disconnected;
    MachineStatus m_status;
    Capabilities m_capabilities; // the controller's, read once at create()
    double m_pollRateHz = 0;
    SoftLimits m_softLimits;
    std::atomic<RequestId> m_lastId{0};
};

} // namespace stepdeck
