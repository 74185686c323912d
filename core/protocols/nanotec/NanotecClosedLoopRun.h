#pragma once
#include "NanotecHostDrive.h"
#include "NanotecSteps.h"
#include "model/CommandResult.h"
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QMap>
#include <QVariantMap>
#include <optional>

namespace stepdeck::nanotec {

class NanotecController;
class NanotecClosedLoop;

enum class ClosedLoopRunKind { Calibration, Reference };

// A calibration or closed-loop reference run in progress (readings: NanotecClosedLoop.h):
// watched on the drive ('$', 'C', 'I') until it is ready again, then its result read back;
// ended early by STOP, PANIC, link loss, a silent drive or its deadline.
class NanotecClosedLoopRun
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::nanotec::NanotecClosedLoop)

public:
    using Kind = ClosedLoopRunKind;
    struct Run
    {
        Kind kind = Kind::Calibration;
        RequestId id = 0;
        quint64 generation = 0;
        QElapsedTimer clock;
        qint64 restoreMode = 1;
        qint64 position = 0;
        std::optional<qint64> encoder;
        bool ended = false;   // the drive said ready; its result is being read
        bool sawBusy = false; // a status word of the run showed the drive busy
    };

    NanotecClosedLoopRun(NanotecController* controller, NanotecClosedLoop& loop);

    static QString runName(Kind kind);
    // 'A' started the run; restoreMode is the motor mode set again after it.
    void begin(RequestId id, Axis axis, Kind kind, qint64 restoreMode);
    void abortAll(ErrorKind kind, const QString& why);
    const Run* find(Axis axis) const;
    QString runDetail(Axis axis) const;

private:
    void monitor(Axis axis, quint64 generation);
    void onMonitored(Axis axis, quint64 generation, qint64 word);
    void readResult(Axis axis, quint64 generation, bool failed);
    QString failureText(Axis axis, Kind kind, int code) const;
    void endRun(Axis axis, ErrorKind kind, const QString& message, const QVariantMap& value = {});
    bool current(Axis axis, quint64 generation) const;
    int deadlineMs(Kind kind) const;

    NanotecController* m_ctl;
    NanotecClosedLoop& m_loop;
    QMap<Axis, Run> m_runs;
    quint64 m_generation = 0;
};

} // namespace stepdeck::nanotec
