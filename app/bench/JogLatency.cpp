// stepdeck-bench --jog-latency: the measurement (JogLatency.h). Arguments, output and the
// default run's child process are in JogLatencyMain.cpp.
#include "JogLatency.h"
#include "BenchDevice.h"
#include "EventWait.h"
#include "jog/JogController.h"
#include "jog/JogPanel.h"
#include "jog/JoystickPad.h"
#include "jog/KeyboardJog.h"
#include "machine/MachineContext.h"
#include "model/ModelInfo.h"
#include <QHBoxLayout>
#include <QMutex>
#include <QTest>
#include <optional>

namespace stepdeck::bench {

namespace {

constexpr Axis kAxis = Axis::X;
// Between presses, after the device and the adapter are at rest: this, plus a spread over one
// poll interval (i * 17 mod interval, 17 coprime to 50), so the presses fall on every phase of
// the poller's cycle instead of always just after a status read.
constexpr int kSettleMs = 60;
constexpr int kFrameBoundMs = 3000; // no press or release frame within this: the run ends

// What the device received, judged in its own thread as the bytes arrive
// (BenchDevice::Config::received), so each figure ends at the arrival of the chunk that
// carried the frame. Model-neutral: the simulator's probes say what a frame did.
// - Start: the first chunk after which the device's axis moves. E-LAB: the first SetJogSpeed
//   <DC4> with a non-zero X rate (the board jogs at once, the host ramps); Nanotec: 'A', which
//   starts the speed-mode run after '!2', 'p1', 'o' and 'd' (6.6) set it up.
// - Stop: the first chunk holding a frame the simulator calls a stop. E-LAB: SetJogSpeed with
//   all three rates zero, sent when the host's jog ramp (JogRamp, "Befehle im Jogbetrieb")
//   has come down to zero; Nanotec: 'S', sent after the zero persisted for two jog ticks and
//   the drive ramped down to its start frequency ('o' = u, 6.2).
class JogProbe
{
public:
    enum class Watch { Nothing, Start, Stop };

    void watch(Watch what)
    {
        QMutexLocker lock(&m_mutex);
        m_watch = what;
        m_hitNs = -1;
    }
    qint64 hitNs() const
    {
        QMutexLocker lock(&m_mutex);
        return m_hitNs;
    }
    void received(Simulator* sim, qint64 arrivedNs) // device thread
    {
        const QList<QByteArray> frames = sim->receivedFrames();
        sim->clearReceivedFrames();
        QMutexLocker lock(&m_mutex);
        if (m_hitNs >= 0 || m_watch == Watch::Nothing)
            return;
        if (m_watch == Watch::Start && sim->isMoving(kAxis))
            m_hitNs = arrivedNs;
        for (const QByteArray& frame : frames) {
            if (m_watch == Watch::Stop && sim->isStopFrame(frame))
                m_hitNs = arrivedNs;
        }
    }

private:
    mutable QMutex m_mutex;
    Watch m_watch = Watch::Nothing;
    qint64 m_hitNs = -1;
};

// The GUI's jog wiring as MainWindow builds it (a MachineContext, its JogController with the
// keyboard as a source, the JogPanel with the pads), without the rest of the window.
struct JogRig
{
    JogRig()
    {
        context = new ui::MachineContext(&window);
        jog = new ui::JogController(context, &window);
        keyboard = new ui::KeyboardJog(&window, &window);
        jog->addSource(keyboard);
        panel = new ui::JogPanel(context, jog, keyboard, &window);
        auto* layout = new QHBoxLayout(&window);
        layout->addWidget(panel);
        window.resize(1000, 560);
        // What the operator would read beside the pad or in the status line: a press that
        // moves nothing says why in the run's note.
        const auto remember = [this](const QString& text) { lastMessage = text; };
        QObject::connect(jog, &ui::JogController::refused, &window, remember);
        QObject::connect(context->session(), &ControllerSession::errorOccurred, &window, remember);
    }
    ~JogRig()
    {
        // The panel's sources tell the controller when they go: before the context they read.
        delete panel;
        delete jog;
        delete keyboard;
        delete context; // the session's close stops what it tracks
    }
    ui::JoystickPad* pad() const { return panel->xyPad(); }
    QPoint padPoint(double deflectionX) const
    {
        return pad()->mapTo(&window, pad()->pointFor(QPointF(deflectionX, 0.0)).toPoint());
    }

    QWidget window;
    ui::MachineContext* context = nullptr;
    ui::JogController* jog = nullptr;
    ui::KeyboardJog* keyboard = nullptr;
    ui::JogPanel* panel = nullptr;
    QString lastMessage;
};

BenchDevice::Config deviceConfig(const ModelInfo& model, const JogLatencyOptions& options,
                                 JogProbe* probe)
{
    BenchDevice::Config config;
    config.paced = options.paced;
    // As for the panic figure: the simulator stands in for a board with a CPU of its own.
    config.realtime = true;
    if (model.capabilities.multiDrive && !model.soak.simulatorAddresses.isEmpty())
        config.addresses = {model.soak.simulatorAddresses.first()};
    config.prepare = model.soak.prepare; // limit switches out of reach of 50 presses one way
    config.received = [probe](Simulator* sim, qint64 arrivedNs) {
        probe->received(sim, arrivedNs);
    };
    return config;
}

// Connects the rig's context as the connection bar does, writes the setup the device needs
// before motion and shows the window active (jog runs only in the active window).
QString connectRig(JogRig& rig, const ModelInfo& model, const QString& port)
{
    ConnectionSpec spec;
    spec.port = port;
    if (model.capabilities.multiDrive && !model.soak.simulatorAddresses.isEmpty())
        spec.options.axisAddresses = {{kAxis, model.soak.simulatorAddresses.first()}};
    QString error;
    if (!rig.context->connectTo(model, spec, &error))
        return QStringLiteral("connect: %1").arg(error);
    if (!waitUntil([&] { return rig.context->isConnected(); }, 5000))
        return QStringLiteral("the link did not come up within 5 s");
    if (const ParameterSet set = setupParameters(model); !set.isEmpty()) {
        RequestId id = 0;
        std::optional<CommandResult> result;
        const auto c = QObject::connect(rig.context->session(), &ControllerSession::requestFinished,
                                        [&](const CommandResult& r) {
                                            if (r.id == id)
                                                result = r;
                                        });
        id = rig.context->writeParameters(set, false);
        waitUntil([&] { return result.has_value(); }, 5000);
        QObject::disconnect(c);
        if (!result || !result->ok())
            return QStringLiteral("setup: %1").arg(result ? result->message : "no result");
    }
    rig.window.show();
    rig.window.activateWindow();
    if (!QTest::qWaitForWindowActive(&rig.window))
        return QStringLiteral("the jog window did not become active");
    if (!waitUntil([&] { return rig.pad()->isEnabled(); }, 2000))
        return QStringLiteral("the pad stayed disabled");
    return {};
}

// The device's axis stands still, the host jogs nothing and its status (read from the device
// after the stop) shows the axis at rest: the next press starts from rest.
bool waitForRest(JogRig& rig, BenchDevice& device)
{
    return waitUntil(
        [&] {
            const AxisStatus a = rig.context->status().axes.value(kAxis);
            if (rig.jog->isJogging() || a.moving || a.jogging || a.motionUnknown ||
                a.commandedVelocity != 0.0)
                return false;
            bool moving = true;
            device.withSimulator([&](Simulator* sim) { moving = sim->isMoving(kAxis); });
            return !moving;
        },
        10000);
}

// One press of the pad at full +X deflection, held kJogHoldMs, and its release: the two
// latencies in ms as far as they were seen, and a note when one was not.
struct PressResult
{
    std::optional<double> pressMs;
    std::optional<double> releaseMs;
    QString note;
};

PressResult pressOnce(JogRig& rig, JogProbe& probe)
{
    PressResult r;
    rig.lastMessage.clear();
    QWindow* handle = rig.window.windowHandle();
    const QPoint at = rig.padPoint(1.0);
    probe.watch(JogProbe::Watch::Start);
    const qint64 pressedNs = nowNs();
    QTest::mousePress(handle, Qt::LeftButton, Qt::NoModifier, at);
    const bool started = waitUntil([&] { return probe.hitNs() >= 0; }, kFrameBoundMs);
    if (started)
        r.pressMs = double(probe.hitNs() - pressedNs) / 1e6;
    waitUntil([&] { return nowNs() - pressedNs >= qint64(kJogHoldMs) * 1000000; }, kJogHoldMs);
    probe.watch(JogProbe::Watch::Stop);
    const qint64 releasedNs = nowNs();
    QTest::mouseRelease(handle, Qt::LeftButton, Qt::NoModifier, at);
    if (!started) {
        r.note =
            QStringLiteral("no jog frame at the device within %1 ms of the press (%2)")
                .arg(kFrameBoundMs)
                .arg(rig.lastMessage.isEmpty() ? QStringLiteral("no message") : rig.lastMessage);
    } else if (!waitUntil([&] { return probe.hitNs() >= 0; }, kFrameBoundMs)) {
        r.note = QStringLiteral("no stop frame at the device within %1 ms of the release")
                     .arg(kFrameBoundMs);
    } else {
        r.releaseMs = double(probe.hitNs() - releasedNs) / 1e6;
    }
    return r;
}

LatencyFigure figureOf(const QList<double>& samples, bool realtime, const QString& note)
{
    LatencyFigure f;
    f.samples = int(samples.size());
    f.deviceRealtime = realtime;
    f.note = note;
    if (!samples.isEmpty()) {
        f.medianMs = median(samples);
        f.p99Ms = percentile(samples, 0.99);
    }
    return f;
}

} // namespace

JogLatencyFigure measureJogLatency(const ModelInfo& model, const JogLatencyOptions& options)
{
    JogLatencyFigure figure;
    figure.model = model.id;
    JogProbe probe;
    BenchDevice device(model, deviceConfig(model, options, &probe));
    JogRig rig;
    QString note;
    if (!device.start(&note))
        note = QStringLiteral("simulator: %1").arg(note);
    else
        note = connectRig(rig, model, device.slavePath());
    QList<double> press;
    QList<double> release;
    const int pollMs = qMax(1, rig.context->session()->spec().options.pollIntervalMs);
    for (int i = 0; note.isEmpty() && i < options.presses; ++i) {
        if (!waitForRest(rig, device)) {
            note = QStringLiteral("the axis did not come to rest within 10 s");
            break;
        }
        waitUntil([] { return false; }, kSettleMs + (i * 17) % pollMs);
        const PressResult r = pressOnce(rig, probe);
        if (r.pressMs)
            press << *r.pressMs;
        if (r.releaseMs)
            release << *r.releaseMs;
        if (!r.note.isEmpty())
            note = QStringLiteral("press %1: %2").arg(i + 1).arg(r.note);
    }
    probe.watch(JogProbe::Watch::Nothing);
    figure.press = figureOf(press, device.realtime(), note);
    figure.release = figureOf(release, device.realtime(), note);
    return figure;
}

} // namespace stepdeck::bench
