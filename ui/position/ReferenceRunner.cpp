#include "ReferenceRunner.h"
#include "machine/MachineContext.h"

namespace stepdeck::ui {

namespace {
constexpr qint64 kStartGraceMs = 3000; // a run that shows no motion this long did not start
}

ReferenceRunner::ReferenceRunner(MachineContext* context, QObject* parent)
    : QObject(parent), m_context(context)
{
    ControllerSession* session = context->session();
    connect(session, &ControllerSession::requestFinished, this, &ReferenceRunner::onResult);
    connect(session, &ControllerSession::statusChanged, this, &ReferenceRunner::onStatus);
    connect(session, &ControllerSession::linkStateChanged, this, [this](LinkState state) {
        if (state != LinkState::Connected && isRunning())
            fail(tr("Referencing aborted: the link is down."));
    });
    connect(context, &MachineContext::panicTriggered, this, [this] {
        if (isRunning())
            fail(tr("Referencing aborted by the panic stop."));
    });
}

QList<ReferenceRunner::Stage> ReferenceRunner::plan(const QMap<Axis, int>& directions,
                                                    const QMap<Axis, int>& order)
{
    QMap<int, Stage> byOrder;
    for (auto it = directions.cbegin(); it != directions.cend(); ++it) {
        if (it.value() != 0)
            byOrder[order.value(it.key(), 1)].insert(it.key(), it.value() < 0 ? -1 : 1);
    }
    return byOrder.values();
}

QList<Axis> ReferenceRunner::currentAxes() const
{
    return isRunning() ? m_stages.at(m_current).keys() : QList<Axis>();
}

void ReferenceRunner::start(const QList<Stage>& stages)
{
    if (isRunning())
        cancel(tr("Referencing restarted."));
    m_stages = stages;
    if (m_stages.isEmpty()) {
        Q_EMIT finished(false, tr("Nothing to reference: every axis is set to skip."));
        return;
    }
    m_current = 0;
    startStage();
}

void ReferenceRunner::cancel(const QString& reason)
{
    if (isRunning())
        fail(reason);
}

void ReferenceRunner::startStage()
{
    m_accepted = false;
    m_sawMotion = false;
    m_sawUnreferenced = false;
    m_phase = Phase::Sent;
    QStringList names;
    for (Axis a : currentAxes())
        names << axisName(a);
    m_stageText = tr("Referencing %1 (stage %2 of %3)\u2026")
                      .arg(names.join(QStringLiteral(", ")))
                      .arg(m_current + 1)
                      .arg(m_stages.size());
    emitProgress();
    m_request = m_context->session()->reference(m_stages.at(m_current));
}

void ReferenceRunner::reachPhase(Phase phase)
{
    if (phase <= m_phase)
        return;
    m_phase = phase;
    emitProgress();
}

void ReferenceRunner::emitProgress()
{
    // Stages done plus the steps of this stage the controller confirmed (the request
    // accepted, its motion seen): known steps of the run, no guess of how far the axis is.
    Q_EMIT progress(m_current * kPhases + int(m_phase), int(m_stages.size()) * kPhases,
                    m_stageText);
}

void ReferenceRunner::onResult(const CommandResult& result)
{
    if (!isRunning() || result.id != m_request)
        return;
    if (!result.ok()) {
        fail(tr("Referencing failed: %1").arg(result.message));
        return;
    }
    m_accepted = true;
    m_acceptedAt.start();
    reachPhase(Phase::Accepted);
    // Models that report arrival (laser axes) finish the request only when the run is over:
    // the status published before this result is the evidence, and no poll follows.
    if (m_context->capabilities().reportsArrival)
        m_sawMotion = true;
    onStatus(m_context->status());
}

void ReferenceRunner::onStatus(const MachineStatus& status)
{
    if (!isRunning())
        return;
    bool allReferenced = true;
    bool moving = status.busy;
    for (Axis a : currentAxes()) {
        const AxisStatus axis = status.axes.value(a);
        allReferenced = allReferenced && axis.referenced;
        moving = moving || axis.moving;
    }
    if (moving)
        reachPhase(Phase::Moving); // also before the request's answer (laser axes)
    if (!m_accepted)
        return;
    m_sawMotion = m_sawMotion || moving;
    m_sawUnreferenced = m_sawUnreferenced || !allReferenced;
    // A status from before the run may still say "referenced": require evidence of the run.
    if (allReferenced && !moving && (m_sawMotion || m_sawUnreferenced)) {
        ++m_current;
        if (m_current >= m_stages.size()) {
            m_current = -1;
            Q_EMIT progress(int(m_stages.size()) * kPhases, int(m_stages.size()) * kPhases,
                            tr("Referenced."));
            Q_EMIT finished(true, tr("All selected axes are referenced."));
            return;
        }
        startStage();
        return;
    }
    if (!moving && (m_sawMotion || m_acceptedAt.elapsed() > kStartGraceMs)) {
        fail(tr("Referencing failed: the run ended before the reference switch was reached."));
    }
}

void ReferenceRunner::fail(const QString& message)
{
    m_current = -1;
    m_accepted = false;
    Q_EMIT finished(false, message);
}

} // namespace stepdeck::ui
