#include "StreamExecutor.h"
#include "Logging.h"
#include "controller/ControllerSession.h"
#include "machine/Machine.h"
#include "motion/ContourFeed.h"
#include <algorithm>
#include <cmath>

namespace stepdeck::motion {

namespace {
constexpr int kWatchMs = 20; // how often the blocks passed are told and room is looked for
// The ticks the board may hold after EndOfFeed run out within the stream's lead (0.2 s) and
// its buffer; a board still moving after this is a fault.
constexpr qint64 kSettleMs = 5000;
} // namespace

std::vector<StepStream> StreamExecutor::streamsOf(const machine::MachineDescription& description,
                                                  const QMap<QString, Capabilities>& capabilities,
                                                  const QMap<QString, ParameterSchema>& schemas,
                                                  const QMap<QString, ParameterSet>& known)
{
    std::vector<StepStream> streams;
    for (const machine::MachineController& c : description.controllers) {
        const auto caps = capabilities.constFind(c.id);
        if (caps == capabilities.cend() || !caps->contourStream)
            continue;
        StepStream s;
        s.controller = c.id;
        s.axisOfSlot.fill(-1);
        s.slotAxes = caps->axes;
        s.scale.axisCount = int(caps->axes.size());
        if (s.scale.axisCount > kMaxAxes)
            continue;
        for (int i = 0; i < s.scale.axisCount; ++i)
            s.scale.stepsPerUnit[size_t(i)] = 1; // a slot no machine axis uses never steps
        for (int i = 0; i < description.axes.size(); ++i) {
            const machine::MachineAxis& axis = description.axes.at(i);
            const int slot = int(s.slotAxes.indexOf(axis.axis));
            if (axis.controller != c.id || slot < 0)
                continue;
            s.axisOfSlot[size_t(slot)] = i;
            s.scale.stepsPerUnit[size_t(slot)] =
                axis.invert ? -axis.stepsPerUnit : axis.stepsPerUnit;
        }
        s.tickRate = tickRate(*caps, schemas.value(c.id), known.value(c.id), &s.tickRefusal);
        streams.push_back(s);
    }
    return streams;
}

double StreamExecutor::tickRate(const Capabilities& caps, const ParameterSchema& schema,
                                const ParameterSet& known, QString* why)
{
    const QString name = QString::fromLatin1(caps.contourTickBelow);
    double rate = caps.contourMaxTickRate;
    if (!name.isEmpty()) {
        const ParameterValue below = known.value(name);
        for (Axis a : caps.axes) {
            const QVariant v = below.perAxis.value(a);
            if (!v.isValid()) {
                *why = tr("a contour's steps run at one tick rate below %1 on every axis, and "
                          "%1 is not known: write the controller's setup first")
                           .arg(schema.displayLabel(name));
                return 0;
            }
            rate = std::min(rate, std::floor(v.toDouble()) - 1);
        }
    }
    if (rate < 1) {
        *why = tr("%1 is too low for a contour's tick (at least 2 steps/s on every axis)")
                   .arg(schema.displayLabel(name));
        return 0;
    }
    return rate;
}

StreamExecutor::StreamExecutor(machine::Machine* machine, const StepStream& stream, QObject* parent)
    : QObject(parent), m_machine(machine), m_stream(stream)
{
    m_watch.setInterval(kWatchMs);
    connect(&m_watch, &QTimer::timeout, this, &StreamExecutor::watch);
}

StreamExecutor::~StreamExecutor()
{
    disconnect(m_results);
}

void StreamExecutor::start(const std::vector<std::optional<double>>& current, double feedFactor)
{
    ControllerSession* s = m_machine->session(m_stream.controller);
    const machine::MachineDescription& d = m_machine->description();
    StepPosition steps{};
    for (int slot = 0; slot < m_stream.scale.axisCount; ++slot) {
        const qint64 count = s->status().axes.value(m_stream.slotAxes.at(slot)).position;
        steps[size_t(slot)] = count;
        const int a = m_stream.axisOfSlot[size_t(slot)];
        if (a < 0)
            continue;
        const std::optional<double> known =
            size_t(a) < current.size() ? current[size_t(a)] : std::nullopt;
        m_end[size_t(slot)] = known ? *known : d.axes.at(a).toUnits(count);
    }
    // The stream counts from the device's steps here (ContourSteps rounds every position as
    // a whole, so a point the program reached exactly stays the step it stands on).
    m_feed = std::make_shared<ContourFeed>(
        ContourSteps(m_stream.scale, m_end, steps, m_stream.tickRate, kMaxFeedFactor));
    m_feed->setFeedFactor(feedFactor);
    // The machine's soft limits hold at every tick too (the check refused a program beyond
    // them first; the controller adds its own when it takes the contour).
    for (int slot = 0; slot < m_stream.scale.axisCount; ++slot) {
        const int a = m_stream.axisOfSlot[size_t(slot)];
        if (a < 0 || !d.axes.at(a).hasSoftLimits())
            continue;
        const machine::MachineAxis& axis = d.axes.at(a);
        const qint64 low = axis.toSteps(*axis.softMinimum);
        const qint64 high = axis.toSteps(*axis.softMaximum);
        m_feed->setStepLimits(slot, axis.name, std::min(low, high), std::max(low, high));
    }
    m_results = connect(s, &ControllerSession::requestFinished, this, &StreamExecutor::onResult);

    const Capabilities caps = s->capabilities();
    const QString name = QString::fromLatin1(caps.feedRateParameter);
    const ParameterValue held = s->status().knownParameters.value(name);
    ParameterValue tick;
    bool holds = true;
    for (Axis a : caps.axes) {
        tick.perAxis.insert(a, qint64(m_stream.tickRate));
        holds = holds && held.perAxis.value(a) == QVariant(qint64(m_stream.tickRate));
    }
    m_watch.start();
    if (holds) {
        giveContour();
        return;
    }
    m_tickWrite = s->writeParameters(ParameterSet{{name, tick}}, false);
}

void StreamExecutor::giveContour()
{
    m_request = m_machine->session(m_stream.controller)->feedContour(m_feed);
    m_given = true;
    qCDebug(lcMotion) << "contour on" << m_stream.controller << "at" << m_stream.tickRate
                      << "ticks/s, request" << m_request;
}

QString StreamExecutor::append(const CanonicalMove& move, const QString& text)
{
    if (m_closed || m_ended)
        return tr("the contour has ended");
    const QString why = m_feed->append(move);
    if (!why.isEmpty())
        return why;
    m_end = move.end;
    m_blocks.push_back(Block{move.line, text});
    // The first block's start is the runner's to tell; a later one that finds the blocks
    // before it all done starts now.
    if (m_blocks.size() == 1 && m_appended > 0)
        Q_EMIT blockStarted(move.line, text);
    ++m_appended;
    return {};
}

bool StreamExecutor::hasRoom() const
{
    return !m_closed && !m_ended && m_feed->canAppend() && m_feed->queuedSeconds() < kAheadSeconds;
}

void StreamExecutor::close()
{
    if (m_closed)
        return;
    m_closed = true;
    m_feed->close();
}

void StreamExecutor::cancel()
{
    close();
    if (!m_given && !m_ended) {
        m_tickWrite = 0;
        finish(false, ErrorKind::None, tr("cancelled before the contour was given"));
    }
}

void StreamExecutor::setFeedFactor(double factor)
{
    if (m_feed)
        m_feed->setFeedFactor(factor);
}

void StreamExecutor::hold(bool held)
{
    if (m_feed)
        m_feed->setHeld(held);
}

int StreamExecutor::currentLine() const
{
    return m_blocks.empty() ? 0 : m_blocks.front().line;
}

void StreamExecutor::onResult(const CommandResult& result)
{
    if (m_ended || result.id == 0)
        return;
    if (result.id == m_tickWrite) {
        m_tickWrite = 0;
        if (!result.ok()) {
            finish(false, result.error,
                   tr("the contour's tick rate %1 was not taken: %2")
                       .arg(m_stream.tickRate)
                       .arg(result.message));
            return;
        }
        giveContour();
        return;
    }
    if (result.id == m_request) {
        m_request = 0;
        onStreamDone(result);
    } else if (result.id == m_settleRead) {
        m_settleRead = 0;
        onSettleRead(result);
    }
}

void StreamExecutor::onStreamDone(const CommandResult& result)
{
    watch();
    if (!result.ok()) {
        finish(false, result.error, result.message);
        return;
    }
    m_settling.start();
    m_settleRead = m_machine->session(m_stream.controller)->refreshStatus();
}

void StreamExecutor::onSettleRead(const CommandResult& result)
{
    if (!result.ok()) {
        finish(false, result.error, result.message);
        return;
    }
    ControllerSession* s = m_machine->session(m_stream.controller);
    bool moving = false;
    for (int slot = 0; slot < m_stream.scale.axisCount; ++slot)
        moving = moving || s->status().axes.value(m_stream.slotAxes.at(slot)).moving;
    if (moving && m_settling.elapsed() < kSettleMs) {
        m_settleRead = s->refreshStatus(); // the board still runs the ticks it holds
        return;
    }
    if (moving) {
        finish(false, ErrorKind::Timeout,
               tr("the board did not come to rest after the contour's last tick"));
        return;
    }
    while (!m_blocks.empty()) { // the board ran to the last appended move's end
        const int line = m_blocks.front().line;
        m_blocks.pop_front();
        m_lastFinished = line;
        Q_EMIT blockFinished(line);
    }
    finish(true, ErrorKind::None, {});
}

void StreamExecutor::watch()
{
    if (m_ended)
        return;
    const qint64 done = m_feed->movesDone();
    while (m_reported < done && !m_blocks.empty()) {
        ++m_reported;
        const int line = m_blocks.front().line;
        m_blocks.pop_front();
        m_lastFinished = line;
        Q_EMIT blockFinished(line);
        if (m_ended)
            return;
        if (!m_blocks.empty())
            Q_EMIT blockStarted(m_blocks.front().line, m_blocks.front().text);
    }
    if (hasRoom())
        Q_EMIT roomForMoves();
}

void StreamExecutor::finish(bool ok, ErrorKind kind, const QString& message)
{
    if (m_ended)
        return;
    m_ended = true;
    m_watch.stop();
    disconnect(m_results);
    if (m_feed && !m_closed)
        m_feed->close(); // a stream still waiting for moves ends (a refused tick write)
    Q_EMIT finished(ok, kind, message);
}

} // namespace stepdeck::motion
