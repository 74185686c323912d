#pragma once
#include <QByteArray>
#include <QMetaType>

namespace stepdeck {

// One chunk of bytes on the link, for the traffic console and logs.
struct TrafficRecord
{
    enum class Direction { Out, In };
    Direction direction = Direction::Out;
    qint64 timestampUs = 0; // monotonic, microseconds since the session started
    QByteArray bytes;
    bool poll = false; // part of the status poller's traffic (the console can hide it)
};

} // namespace stepdeck

Q_DECLARE_METATYPE(stepdeck::TrafficRecord)
