#pragma once
#include "transport/WireBudget.h"
#include <QByteArray>
#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <deque>
#include <functional>

namespace stepdeck::bench {

// A serial wire in one direction: bytes leave back to back, each taking one character time
// (start + data + parity + stop bits at the baud rate; core's WireBudget, the same model the
// E-LAB stream paces by), and are delivered when their last bit would have arrived. Times run on a
// virtual clock, so no rounding accumulates; delivery itself is quantised by Qt's millisecond
// timers to within +-0.5 ms (kToleranceUs) of the exact time, early and late alike, without
// busy-waiting.
class WirePacer : public QObject
{
public:
    WirePacer(double characterUs, std::function<void(const QByteArray&)> deliver,
              QObject* parent = nullptr);

    void push(const QByteArray& bytes); // the bytes enter the wire now

private:
    struct Chunk
    {
        QByteArray bytes;
        double startUs = 0; // when the first remaining byte started on the wire
    };
    static constexpr double kToleranceUs = 500;

    void release();
    double nowUs() const { return double(m_clock.nsecsElapsed()) / 1000.0; }

    double m_characterUs;
    std::function<void(const QByteArray&)> m_deliver;
    std::deque<Chunk> m_chunks;
    WireBudget m_wire; // when the bytes handed to the wire start and finish
    QElapsedTimer m_clock;
    QTimer m_timer;
};

} // namespace stepdeck::bench
