// What the closed-loop panel shows: results of the check, the runs and the switch, the state
// the adapter keeps for this connection, the progress of a run and the next step.
#include "ClosedLoopPanel.h"
#include "OneLineLabel.h"
#include "machine/MachineContext.h"
#include "model/ClosedLoop.h"
#include <QComboBox>
#include <QProgressBar>

namespace stepdeck::ui {

namespace cl = closedloop;
using drives::elided;

namespace {
QString runResultText(const QString& result)
{
    if (result == cl::kResultRunning)
        return ClosedLoopPanel::tr("running\u2026");
    if (result == cl::kResultDone)
        return ClosedLoopPanel::tr("done in this connection");
    if (result == cl::kResultFailed)
        return ClosedLoopPanel::tr("FAILED: the drive reported an error");
    if (result == cl::kResultAborted)
        return ClosedLoopPanel::tr("aborted: not complete");
    return ClosedLoopPanel::tr("not run in this connection (the drive cannot report it)");
}

QString seconds(const QVariant& ms)
{
    return QString::number(ms.toDouble() / 1000.0, 'f', 1);
}
} // namespace

void ClosedLoopPanel::onResult(const CommandResult& result)
{
    if (result.id != 0 && result.id == m_stateRequest) {
        m_stateRequest = 0;
        if (result.ok())
            onState(result.value.toMap());
        return;
    }
    if (result.id == 0 || result.id != m_pending)
        return;
    const Step step = m_step;
    m_pending = 0;
    m_step = Step::None;
    m_poll.stop();
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    const QVariantMap value = result.value.toMap();
    QString text = result.message;
    if (result.ok() && step == Step::Check) {
        onCheck(value);
        text.clear();
    } else if (result.ok() && (step == Step::Calibrate || step == Step::Reference)) {
        m_progress->setValue(1);
        elided(m_progressText)
            ->setFullText(tr("ended after %1 s: position %2, encoder %3 (read back)")
                              .arg(seconds(value.value(cl::kDurationMs)),
                                   value.value(cl::kPosition).toString(),
                                   value.value(cl::kEncoderPosition).toString()));
        text = step == Step::Calibrate ? tr("Calibration run done.")
                                       : tr("Reference run done: the axis is referenced.");
    } else if (result.ok() && (step == Step::Enable || step == Step::Disable)) {
        const bool on = value.value(cl::kEnabled).toBool();
        const auto axis = axisFromName(value.value(cl::kAxis).toString());
        ParameterValue known;
        if (axis)
            known.perAxis.insert(*axis, on); // the setup page shows what the drive kept
        m_context->addKnownParameters({{value.value(cl::kParameter).toString(), known}}, true);
        text = on ? tr("Closed loop is on (read back).") : tr("Closed loop is off (read back).");
    } else if (result.ok() && step == Step::ResetError) {
        text = tr("Position error cleared; the position is the encoder's now.");
    }
    elided(m_message)->setFullText(text);
    updateEnabled();
    pollState();
}

void ClosedLoopPanel::onCheck(const QVariantMap& v)
{
    const QStringList problems = v.value(cl::kProblems).toStringList();
    m_motorDataFit = problems.isEmpty();
    QString text =
        tr("pole pairs %1, encoder %2 increments per %3 revolution(s), step angle "
           "%4\u00b0; encoder position %5, position %6")
            .arg(v.value(cl::kMotorPolePairs).toString(),
                 v.value(cl::kEncoderIncrements).toString(),
                 v.value(cl::kEncoderRevolutions).toString(), v.value(cl::kStepAngle).toString(),
                 v.value(cl::kEncoderPosition).toString(), v.value(cl::kPosition).toString());
    if (!problems.isEmpty())
        text = tr("CANNOT WORK: %1 (%2)").arg(problems.join(QStringLiteral("; ")), text);
    elided(m_motorData)->setFullText(text);
    onState(v);
}

void ClosedLoopPanel::onState(const QVariantMap& state)
{
    if (state.value(cl::kAxis).toString() != m_axis->currentText())
        return; // an answer for the axis shown before
    m_state = state;
    elided(m_calibration)->setFullText(runResultText(state.value(cl::kCalibration).toString()));
    elided(m_referenceState)->setFullText(runResultText(state.value(cl::kReferenceRun).toString()));
    elided(m_closedLoop)
        ->setFullText(!state.contains(cl::kEnabled) ? tr("unknown: not read in this connection")
                      : state.value(cl::kEnabled).toBool() ? tr("on (read back)")
                                                           : tr("off (read back)"));
    if (state.value(cl::kRun).toString() != cl::kRunNone)
        showProgress(state);
    showNextStep();
}

void ClosedLoopPanel::showProgress(const QVariantMap& state)
{
    const bool calibration = state.value(cl::kRun).toString() == cl::kRunCalibration;
    const QString encoder = state.contains(cl::kEncoderPosition)
                                ? state.value(cl::kEncoderPosition).toString()
                                : tr("not read yet");
    elided(m_progressText)
        ->setFullText((calibration ? tr("calibration run: %1 s, position %2, encoder %3")
                                   : tr("reference run: %1 s, position %2, encoder %3"))
                          .arg(seconds(state.value(cl::kElapsedMs)),
                               state.value(cl::kPosition).toString(), encoder));
}

void ClosedLoopPanel::showNextStep()
{
    const QString calibration = m_state.value(cl::kCalibration).toString();
    const QString reference = m_state.value(cl::kReferenceRun).toString();
    QString next;
    if (!m_context->isConnected())
        next = tr("Connect, then check the motor data.");
    else if (!m_motorDataFit)
        next = tr("Next: 1, check the motor data.");
    else if (!*m_motorDataFit)
        next = tr("Correct the motor data first (Setup, closed loop).");
    else if (calibration == cl::kResultFailed || calibration == cl::kResultAborted)
        next = tr("Next: 2, the calibration run again (is the encoder connected?).");
    else if (reference != cl::kResultDone && calibration != cl::kResultDone)
        next = tr("Next: 2, the calibration run for a newly connected motor; else 3.");
    else if (reference != cl::kResultDone)
        next = tr("Next: 3, the reference run.");
    else if (!m_state.value(cl::kEnabled).toBool())
        next = tr("Next: 4, closed loop on.");
    else
        next = tr("Closed loop is on.");
    elided(m_next)->setFullText(next);
}

} // namespace stepdeck::ui
