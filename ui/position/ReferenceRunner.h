#pragma once
#include "model/CommandResult.h"
#include "model/MachineStatus.h"
#include <QElapsedTimer>
#include <QObject>

namespace stepdeck::ui {

class MachineContext;

// Runs a reference (homing) sequence stage by stage: each stage is one reference request for
// the axes that share an order number (default: Z first, then X and Y together). A stage is
// done when the controller reports those axes referenced; it fails when the motion ends
// without that, when the request fails, or on stop, panic or link loss.
class ReferenceRunner : public QObject
{
    Q_OBJECT
public:
    using Stage = QMap<Axis, int>; // axis -> direction (-1/+1)

    explicit ReferenceRunner(MachineContext* context, QObject* parent = nullptr);

    void start(const QList<Stage>& stages);
    void cancel(const QString& reason);
    bool isRunning() const { return m_current >= 0; }
    int stageCount() const { return int(m_stages.size()); }
    int currentStage() const { return m_current; }
    QList<Axis> currentAxes() const;

    // Builds stages from directions (0 = skip) and order numbers; equal numbers run together.
    static QList<Stage> plan(const QMap<Axis, int>& directions, const QMap<Axis, int>& order);

Q_SIGNALS:
    // done of total steps: each stage counts kPhases (sent, accepted by the controller, its
    // motion reported, referenced), so the bar moves during a stage too (issue 16).
    void progress(int done, int total, const QString& text);
    void finished(bool ok, const QString& message);

public:
    static constexpr int kPhases = 3;

private:
    enum class Phase { Sent = 0, Accepted = 1, Moving = 2 };
    void startStage();
    void reachPhase(Phase phase);
    void emitProgress();
    void onResult(const CommandResult& result);
    void onStatus(const MachineStatus& status);
    void fail(const QString& message);

    MachineContext* m_context;
    QList<Stage> m_stages;
    int m_current = -1;
    RequestId m_request = 0;
    bool m_accepted = false;
    bool m_sawMotion = false;
    bool m_sawUnreferenced = false;
    QElapsedTimer m_acceptedAt;
    Phase m_phase = Phase::Sent;
    QString m_stageText;
};

} // namespace stepdeck::ui
