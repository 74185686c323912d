#pragma once
#include "ElabCodec.h"
#include "model/Axis.h"
#include "motion/ContourFeed.h"
#include <QVector>
#include <memory>

namespace stepdeck::elab {

// The host side of a <DC2> single-step stream (manual: SetFeedStepXYZ). Produces the step
// bytes in chunks of whole <DC2><byte> pairs (a pair is never split, so a stop or a poll
// written between chunks can never be taken for step data) and keeps count of what was
// handed to the transport. Three sources: explicit single steps, a straight line between
// two points split into single steps (integer Bresenham: every axis arrives exactly, no step
// lost or duplicated), or a contour laid on ticks (motion::ContourFeed, issue 30: slots 0, 1, 2
// are X, Y, Z; a vector without steps is a tick without a step). Pure: the adapter owns flow
// control and writing.
class ElabCtlStream
{
public:
    // The most pairs beyond what the line can have carried (ElabExchangeQueue's wire window):
    // what may still arrive after the board's XOFF. Chunks are at most this long.
    static constexpr int kChunkSteps = 8;

    // Empty string when every step is -1, 0 or +1 on X, Y or Z; else why not.
    static QString validate(const QVector<AxisVector>& steps);

    void startSteps(const QVector<AxisVector>& steps);
    void startLine(const Triple<qint64>& delta);
    void startContour(std::shared_ptr<motion::ContourFeed> contour);
    void clear();

    bool isActive() const { return m_active; }
    void setActive(bool active) { m_active = active; }
    qint64 total() const { return m_contour ? m_sent + m_buffered.size() : m_total; }
    qint64 sent() const { return m_sent; }
    bool atEnd() const;
    // A contour whose next tick is not known yet (its next move not given): nothing to send
    // until the feed wakes the adapter.
    bool waiting();
    const std::shared_ptr<motion::ContourFeed>& contour() const { return m_contour; }
    QList<Axis> axes() const; // axes that take at least one step

    // The next chunk of up to maxSteps pairs; *delta receives the signed steps per axis in it.
    QByteArray nextChunk(int maxSteps, Triple<qint64>* delta);

    // Flow control from the board (XOFF/XON) and the chunk inside the transport.
    bool pausedByDevice = false;
    bool chunkInFlight = false;
    // STOP during a contour (issue 47): no further pair is built; the stream ends with
    // EndOfFeed once the chunk on its way has left (ElabCtlMotionOps::stopContour).
    bool stopAsked = false;
    quint64 requestId = 0;

private:
    Triple<int> stepAt(qint64 index) const; // 0-based
    void fillFromContour(int want);

    bool m_active = false;
    QVector<AxisVector> m_steps; // explicit source
    Triple<qint64> m_line{};     // line source (when m_steps is empty)
    qint64 m_total = 0;
    qint64 m_sent = 0;
    std::shared_ptr<motion::ContourFeed> m_contour; // contour source
    QVector<motion::StepTick> m_buffered;           // pulled from it, not sent yet
};

} // namespace stepdeck::elab
