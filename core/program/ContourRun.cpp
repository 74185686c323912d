#include "ContourRun.h"
#include "ProgramLogging.h"
#include "controller/ControllerSession.h"
#include "machine/Machine.h"
#include "motion/ContourFeed.h"
#include <algorithm>

namespace stepdeck::program {

namespace {
constexpr int kWatchMs = 20; // how often the blocks passed are told and room is looked for
// The ticks the board may hold after EndOfFeed run out within the stream's lead (0.2 s) and
// its buffer; a board still moving after this is a fault.
constexpr qint64 kSettleMs = 5000;
} // namespace

ContourRun::ContourRun(machine::Machine* machine, const ContourMoves::Stream& stream,
                       QObject* parent)
    : QObject(parent), m_machine(machine), m_stream(stream)
{
    m_watch.setInterval(kWatchMs);
    connect(&m_watch, &QTimer::timeout, this, &ContourRun::watch);
}

ContourRun::~ContourRun()
{
    disconnect(m_results);
}

void ContourRun::start(const AxisPositions& current, double feedFactor)
{
    ControllerSession* s = m_machine->session(m_stream.controller);
    const machine::MachineDescription& d = m_machine->description();
    motion::StepPosition steps{};
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
    m_feed = std::make_shared<motion::ContourFeed>(
        motion::ContourSteps(m_stream.scale, m_end, steps, m_stream.tickRate, kMaxFeedFactor));
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
    m_results = connect(s, &ControllerSession::requestFinished, this, &ContourRun::onResult);

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

void ContourRun::giveContour()
{
    m_request = m_machine->session(m_stream.controller)->feedContour(m_feed);
    m_given = true;
    qCDebug(lcProgram) << "contour on" << m_stream.controller << "at" << m_stream.tickRate
                       << "ticks/s, request" << m_request;
}

QString ContourRun::append(const motion::CanonicalMove& move, const QString& text)
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

bool ContourRun::hasRoom() const
{
    return !m_closed && !m_ended && m_feed->canAppend() && m_feed->queuedSeconds() < kAheadSeconds;
}

void ContourRun::close()
{
    if (m_closed)
        return;
    m_closed = true;
    m_feed->close();
}

void ContourRun::cancel()
{
    close();
    if (!m_given && !m_ended) {
        m_tickWrite = 0;
        finish(false, ErrorKind::None, tr("cancelled before the contour was given"));
    }
}

void ContourRun::setFeedFactor(double factor)
{
    if (m_feed)
        m_feed->setFeedFactor(factor);
}

void ContourRun::hold(bool held)
{
    if (m_feed)
        m_feed->setHeld(held);
}

int ContourRun::currentLine() const
{
    return m_blocks.empty() ? 0 : m_blocks.front().line;
}

void ContourRun::onResult(const CommandResult& result)
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

void ContourRun::onStreamDone(const CommandResult& result)
{
    watch();
    if (!result.ok()) {
        finish(false, result.error, result.message);
        return;
    }
    m_settling.start();
    m_settleRead = m_machine->session(m_stream.controller)->refreshStatus();
}

void ContourRun::onSettleRead(const CommandResult& result)
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

void ContourRun::watch()
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

void ContourRun::finish(bool ok, ErrorKind kind, const QString& message)
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

} // namespace stepdeck::program
