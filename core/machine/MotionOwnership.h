#pragma once
#include <QObject>
#include <QPointer>
#include <QString>

namespace stepdeck::machine {

// Who moves the machine (issue 49 item 4, docs/architecture.md "One motion path"): one owner at
// a time -- a program's run or an MDI line, Go to included (each a ProgramRunner) -- so that
// they exclude each other in core, not through the window, as LinuxCNC's task grants motion to
// one mode at a time. Pure bookkeeping; Machine keeps one and, at STOP, PANIC and close, tells
// the holder to end its work (Machine::abortRequested). An owner that is deleted holds nothing.
class MotionOwnership
{
public:
    // Takes the machine's motion for `owner`, described by `what` ("a program runs"): true when
    // taken or already held by `owner`; false with *why the holder's description when another
    // holds it.
    bool claim(const QObject* owner, const QString& what, QString* why = nullptr);
    void release(const QObject* owner); // nothing unless `owner` holds it
    bool isHeldBy(const QObject* owner) const;
    bool isFree() const { return m_owner.isNull(); }
    QString holder() const; // what holds it; empty when free
    // The holder lends the machine to the operator's hands while it holds (a run paused at M0
    // or M6: jogging to touch off, issue 47 item 2): manual motion is admitted then. Only the
    // holder lends; a new claim or a release ends it.
    void setLent(const QObject* owner, bool lent);
    bool admitsManualMotion() const { return isFree() || m_lent; }

private:
    QPointer<QObject> m_owner;
    QString m_what;
    bool m_lent = false;
};

} // namespace stepdeck::machine
