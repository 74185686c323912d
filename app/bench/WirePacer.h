#pragma once
#include "PreciseWakeup.h"
#include "transport/WireBudget.h"
#include <QByteArray>
#include <QObject>
#include <deque>
#include <functional>

namespace stepdeck::bench {

// A serial wire in one direction: bytes leave back to back, each taking one character time
// (start + data + parity + stop bits at the baud rate; core's WireBudget, the same model the
// E-LAB stream paces by), and each is delivered when its last bit has arrived. The wake-ups are
// precise (PreciseWakeup: a timerfd, no busy-waiting) but come some tens of microseconds late
// on a loaded or virtual machine; the pacer arms them early by their measured mean latency
// (PreciseWakeup::latencyNs, at most 100 us), so deliveries are on time on average and each
// within about that latency of its exact time, early or late, instead of always late. Bytes due
// within kCoalesceNs of a wake-up are delivered with it. Times run on a virtual clock, so no
// rounding accumulates.
//
// Delivery: EachCharacter hands every byte on as it arrives (a board's UART interrupts per
// character, so a device acts on the first of two requests before the second has arrived);
// WholeWrites hands each push()'s bytes on together, in a deliver() of their own, when the last
// of them has arrived (towards the
// host, which acts only on complete replies and whose adapter hands bytes on in bunches anyway;
// it saves the host a wake-up per character).
class WirePacer : public QObject
{
public:
    enum class Delivery { EachCharacter, WholeWrites };

    WirePacer(double characterUs, std::function<void(const QByteArray&)> deliver,
              QObject* parent = nullptr, Delivery delivery = Delivery::EachCharacter);

    void push(const QByteArray& bytes); // the bytes enter the wire now

    static constexpr qint64 kCoalesceNs = 20000; // 20 us: a tenth of a character at 57600 8N2

private:
    struct Chunk
    {
        QByteArray bytes;
        qint64 startNs = 0; // when the first remaining byte started on the wire
    };

    void release();

    double m_characterNs;
    Delivery m_delivery;
    std::function<void(const QByteArray&)> m_deliver;
    std::deque<Chunk> m_chunks;
    WireBudget m_wire; // when the bytes handed to the wire start and finish
    PreciseWakeup m_wakeup;
};

} // namespace stepdeck::bench
