#pragma once
// Small helpers shared by StepDeck tests (header-only).
#include <QByteArray>
#include <QSignalSpy>
#include <QtTest>

namespace stepdeck::test {

// Every byte value 0x00..0xFF once, in order: catches any layer that swallows or maps
// control characters (XON 0x11, XOFF 0x13, NUL, CR/LF) or sign-extends 0xFF.
inline QByteArray allByteValues()
{
    QByteArray out(256, '\0');
    for (int i = 0; i < 256; ++i)
        out[i] = char(i);
    return out;
}

// Concatenates every dataReceived-style payload recorded by a spy (first argument).
inline QByteArray joinedBytes(const QSignalSpy& spy)
{
    QByteArray out;
    for (const QList<QVariant>& args : spy)
        out += args.at(0).toByteArray();
    return out;
}

// A negative check: true if the spy recorded nothing new within `ms`. Waits on the event
// loop (QSignalSpy::wait), never sleeps, so queued work keeps running meanwhile.
inline bool staysQuiet(QSignalSpy& spy, int ms)
{
    const qsizetype before = spy.count();
    spy.wait(ms);
    return spy.count() == before;
}

} // namespace stepdeck::test
