#pragma once
#include "NanotecHostDrive.h"
#include "NanotecSteps.h"
#include "model/CommandResult.h"
#include <QCoreApplication>

namespace stepdeck::nanotec {

class NanotecController;
class NanotecExchange;

// Positioning (!1, p1/p2, 6.6), reference runs (p3/p4 with d) and velocity moves (!2, p1) on
// the drives of a Nanotec bus, and the refusals of a move the drive cannot run now.
class NanotecMotion
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::nanotec::NanotecController)

public:
    explicit NanotecMotion(NanotecController& controller);

    void moveRelative(RequestId id, const AxisVector& steps);
    void moveAbsolute(RequestId id, const AxisVector& targets);
    void referenceWithType(RequestId id, const QMap<Axis, int>& directions, bool internal);
    void velocityMove(RequestId id, const AxisVector& stepsPerS);
    // verify: per axis the settings that must read back before 'A' ('!', 'p', 's', 'd', 'o');
    // learn: settings read into the held settings unless held at 0 already ('N': a start
    // keeps the held settings only while no follow-up record follows, 6.16).
    void startPositioning(RequestId id, const QMap<Axis, QList<QByteArray>>& setup,
                          bool referenceRun,
                          const QMap<Axis, QMap<QByteArray, qint64>>& verify = {},
                          const QList<char>& learn = {});
    // Why the drive of axis cannot start a motion now (empty: it can).
    // referenceRun: a position error does not refuse it (the run clears it first, 5.14).
    QString motionRefusal(Axis axis, bool needsPosition, bool referenceRun = false) const;
    QString belowStartFrequency(Axis axis, double stepsPerS) const; // non-empty: refused

private:
    QString unknownAxes(const QList<Axis>& axes) const;

    NanotecController& m_ctl;
    NanotecExchange& m_link;
};

} // namespace stepdeck::nanotec
