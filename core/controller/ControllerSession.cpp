#include "ControllerSession.h"
#include "Logging.h"
#include "transport/LoopbackTransport.h"
#include "transport/TransportFactory.h"
#include <QCoreApplication>
#include <QEvent>
#include <QSemaphore>

namespace stepdeck {

namespace {
// A posted function: lets the session choose the event priority of each call, so stop,
// panic and jog updates overtake ordinary work waiting in the controller thread's queue.
class FunctionEvent : public QEvent
{
public:
    static QEvent::Type eventType()
    {
        static const int type = QEvent::registerEventType();
        return QEvent::Type(type);
    }
    explicit FunctionEvent(std::function<void()> fn) : QEvent(eventType()), m_fn(std::move(fn)) {}
    void run() { m_fn(); }

private:
    std::function<void()> m_fn;
};

class ThreadContext : public QObject
{
public:
    using QObject::QObject;
    bool event(QEvent* e) override
    {
        if (e->type() == FunctionEvent::eventType()) {
            static_cast<FunctionEvent*>(e)->run();
            return true;
        }
        return QObject::event(e);
    }
};
} // namespace

ControllerSession::ControllerSession(QObject* parent) : QObject(parent)
{
    m_thread.setObjectName(QStringLiteral("controller"));
}

ControllerSession::~ControllerSession()
{
    destroy();
}

bool ControllerSession::create(const ModelInfo& modelInfo, const ConnectionSpec& connection,
                               QString* error)
{
    destroy();
    if (!modelInfo.createController ||
        (connection.port == QLatin1String("sim") && !modelInfo.createSimulator)) {
        if (error)
            *error = tr("model %1 cannot be built in this program").arg(modelInfo.id);
        return false;
    }
    m_model = &modelInfo;
    m_spec = connection;
    const ConnectionSpec& spec = m_spec;
    m_thread.start();
    m_context = new ThreadContext;
    m_context->moveToThread(&m_thread);

    const ModelInfo* model = m_model;
    Controller* controller = nullptr;
    Simulator* simulator = nullptr;
    Capabilities capabilities;
    ThreadContext* context = static_cast<ThreadContext*>(m_context);
    const SoftLimits limits = m_softLimits;
    // Build the stack inside the controller thread so every QObject has the right affinity.
    QMetaObject::invokeMethod(
        m_context,
        [&] {
            Transport* transport = nullptr;
            if (spec.port == QLatin1String("sim")) {
                auto [hostEnd, deviceEnd] = LoopbackTransport::createPair(context);
                SimulatorOptions simOptions = spec.simulator;
                simOptions.line = model->line;
                // A bus simulator serves the drives the axis map names unless told otherwise.
                if (simOptions.addresses.isEmpty())
                    simOptions.addresses = spec.options.axisAddresses.values();
                simulator = model->createSimulator(simOptions);
                simulator->setParent(context);
                deviceEnd->open(model->line);
                simulator->attach(deviceEnd);
                transport = hostEnd;
            } else {
                transport = createTransport(spec.port, context);
            }
            controller = model->createController(transport, spec.options);
            controller->setParent(context);
            controller->setSoftLimits(limits);
            capabilities = controller->capabilities(); // may depend on the axis map
        },
        Qt::BlockingQueuedConnection);
    m_controller = controller;
    m_simulator = simulator;
    m_capabilities = capabilities;

    connect(m_controller, &Controller::linkStateChanged, this,
            [this](LinkState state, const QString& reason) {
                m_linkState = state;
                Q_EMIT linkStateChanged(state, reason);
            });
    connect(m_controller, &Controller::statusChanged, this, [this](const MachineStatus& status) {
        m_status = status;
        Q_EMIT statusChanged(status);
    });
    connect(m_controller, &Controller::pollRateChanged, this, [this](double hz) {
        m_pollRateHz = hz;
        Q_EMIT pollRateChanged(hz);
    });
    connect(m_controller, &Controller::requestFinished, this, &ControllerSession::requestFinished);
    connect(m_controller, &Controller::errorOccurred, this, &ControllerSession::errorOccurred);
    connect(m_controller, &Controller::traffic, this, &ControllerSession::traffic);
    connect(m_controller, &Controller::jogRefused, this, &ControllerSession::jogRefused);
    qCInfo(lcSession) << "created" << modelInfo.id << "on" << spec.port;
    return true;
}

void ControllerSession::destroy()
{
    if (!m_context)
        return;
    QObject* context = m_context;
    // The safety contract first: the adapter's stop goes out and is flushed before the port
    // closes. That close is asynchronous (it waits, bounded, for the stop's reply), so this
    // thread waits for closeFinished -- the controller thread keeps running meanwhile.
    auto closed = std::make_shared<QSemaphore>();
    QMetaObject::invokeMethod(
        context,
        [context, closed] {
            const QList<Controller*> controllers = context->findChildren<Controller*>();
            for (Controller* c : controllers) {
                QObject::connect(c, &Controller::closeFinished, c, [closed] { closed->release(); });
                c->closeLink();
            }
            if (controllers.isEmpty())
                closed->release();
        },
        Qt::QueuedConnection);
    if (!closed->tryAcquire(1, kDestroyCloseWaitMs))
        qCWarning(lcSession) << "close did not finish within" << kDestroyCloseWaitMs << "ms";
    QMetaObject::invokeMethod(
        context, [context] { delete context; }, Qt::BlockingQueuedConnection);
    m_thread.quit();
    m_thread.wait();
    m_context = nullptr;
    m_controller = nullptr;
    m_simulator = nullptr;
    m_linkState = LinkState::Disconnected;
}

Capabilities ControllerSession::capabilities() const
{
    return m_controller ? m_capabilities : m_model ? m_model->capabilities : Capabilities{};
}

ParameterSchema ControllerSession::schema() const
{
    return m_model ? m_model->schema : ParameterSchema{};
}

void ControllerSession::post(std::function<void(Controller*)> fn, bool urgent)
{
    if (!m_controller)
        return;
    Controller* controller = m_controller;
    QCoreApplication::postEvent(m_context, new FunctionEvent([controller, fn] { fn(controller); }),
                                urgent ? Qt::HighEventPriority : Qt::NormalEventPriority);
}

RequestId ControllerSession::submit(std::function<void(Controller*, RequestId)> call, bool urgent)
{
    const RequestId id = nextId();
    if (!m_controller) {
        Q_EMIT requestFinished(
            CommandResult::failure(id, ErrorKind::LinkDown, tr("no controller session")));
        return id;
    }
    post([call, id](Controller* c) { call(c, id); }, urgent);
    return id;
}

RequestId ControllerSession::open()
{
    return submit([](Controller* c, RequestId id) { c->openLink(id); });
}

void ControllerSession::close()
{
    post([](Controller* c) { c->closeLink(); }, true);
}

RequestId ControllerSession::readParameters(const QStringList& names)
{
    return submit([=](Controller* c, RequestId id) { c->readParameters(id, names); });
}

RequestId ControllerSession::writeParameters(const ParameterSet& values, bool verify)
{
    return submit([=](Controller* c, RequestId id) { c->writeParameters(id, values, verify); });
}

// Moves are checked against the soft limits in the controller thread, with the controller's
// own status, before the adapter sees them (Controller::guarded*).
RequestId ControllerSession::moveRelative(const AxisVector& steps)
{
    return submit([=](Controller* c, RequestId id) { c->guardedMoveRelative(id, steps); });
}

RequestId ControllerSession::moveAbsolute(const AxisVector& targets)
{
    return submit([=](Controller* c, RequestId id) { c->guardedMoveAbsolute(id, targets); });
}

RequestId ControllerSession::jogStep(const AxisVector& steps, const AxisVelocities& stepsPerS)
{
    return submit([=](Controller* c, RequestId id) { c->jogStep(id, steps, stepsPerS); });
}

RequestId ControllerSession::feed(const AxisVector& steps)
{
    return submit([=](Controller* c, RequestId id) { c->guardedFeed(id, steps); });
}

RequestId ControllerSession::feedStream(const QVector<AxisVector>& steps)
{
    return submit([=](Controller* c, RequestId id) { c->guardedFeedStream(id, steps); });
}

RequestId ControllerSession::feedContour(std::shared_ptr<motion::ContourFeed> contour)
{
    return submit([=](Controller* c, RequestId id) { c->feedContour(id, contour); });
}

RequestId ControllerSession::reference(const QMap<Axis, int>& directions)
{
    return submit([=](Controller* c, RequestId id) { c->reference(id, directions); });
}

RequestId ControllerSession::velocityMove(const AxisVector& stepsPerS)
{
    return submit([=](Controller* c, RequestId id) { c->guardedVelocityMove(id, stepsPerS); });
}

RequestId ControllerSession::stop()
{
    return submit([](Controller* c, RequestId id) { c->stop(id); }, true);
}

RequestId ControllerSession::panic()
{
    return submit([](Controller* c, RequestId id) { c->panic(id); }, true);
}

RequestId ControllerSession::reset()
{
    return submit([](Controller* c, RequestId id) { c->reset(id); }, true);
}

RequestId ControllerSession::setSpindle(int rpm)
{
    return submit([=](Controller* c, RequestId id) { c->setSpindle(id, rpm); });
}

RequestId ControllerSession::setCoolant(bool on)
{
    return submit([=](Controller* c, RequestId id) { c->setCoolant(id, on); });
}

RequestId ControllerSession::setDrivePower(int percent)
{
    return submit([=](Controller* c, RequestId id) { c->setDrivePower(id, percent); });
}

RequestId ControllerSession::refreshStatus()
{
    return submit([](Controller* c, RequestId id) { c->refreshStatus(id); });
}

RequestId ControllerSession::sendRaw(const QByteArray& bytes)
{
    return submit([=](Controller* c, RequestId id) { c->sendRaw(id, bytes); });
}

RequestId ControllerSession::scanBus()
{
    return submit([](Controller* c, RequestId id) { c->scanBus(id); });
}

RequestId ControllerSession::modelOperation(const QString& name, const QVariantMap& args)
{
    return submit([=](Controller* c, RequestId id) { c->modelOperation(id, name, args); });
}

void ControllerSession::setPollInterval(int ms)
{
    post([ms](Controller* c) { c->setPollInterval(ms); });
}

void ControllerSession::setJogVelocity(const AxisVelocities& targets)
{
    post([targets](Controller* c) { c->setJogVelocity(targets); }, true);
}

void ControllerSession::endJog()
{
    post([](Controller* c) { c->endJog(); }, true);
}

void ControllerSession::setJogAcceleration(double stepsPerS2)
{
    post([stepsPerS2](Controller* c) { c->setJogAcceleration(stepsPerS2); });
}

void ControllerSession::setSoftLimits(const SoftLimits& limits)
{
    m_softLimits = limits;
    post([limits](Controller* c) { c->setSoftLimits(limits); }, true);
}

void ControllerSession::withSimulator(std::function<void(Simulator*)> fn)
{
    if (!m_simulator)
        return;
    Simulator* sim = m_simulator;
    QCoreApplication::postEvent(m_context, new FunctionEvent([sim, fn] { fn(sim); }));
}

} // namespace stepdeck
