#include "ClosedLoopPanel.h"
#include "OneLineLabel.h"
#include "common/Dialogs.h"
#include "machine/MachineContext.h"
#include "model/ClosedLoop.h"
#include "model/ModelOperations.h"
#include <QComboBox>
#include <QGridLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>

namespace stepdeck::ui {

namespace cl = closedloop;
using drives::elided;

namespace {
constexpr int kPollMs = 250; // progress of a run: what the drive reads back

QPushButton* button(const QString& text, const QString& name, const QString& tip, QWidget* parent)
{
    auto* b = new QPushButton(text, parent);
    b->setObjectName(name);
    b->setToolTip(tip);
    return b;
}
} // namespace

ClosedLoopPanel::ClosedLoopPanel(MachineContext* context, QWidget* parent)
    : QGroupBox(tr("Closed loop (manual 8.1)"), parent), m_context(context),
      m_axis(new QComboBox(this)), m_direction(new QComboBox(this)),
      m_check(button(tr("1 Check motor data"), QStringLiteral("closedLoopCheck"),
                     tr("Read pole pairs, encoder increments and revolutions, the encoder "
                        "position and whether closed loop is on; nothing moves"),
                     this)),
      m_calibrate(button(tr("2 Calibration run\u2026"), QStringLiteral("closedLoopCalibrate"),
                         tr("Mode 101: once for every newly connected motor, also of the same "
                            "type. The motor turns."),
                         this)),
      m_reference(button(tr("3 Reference run\u2026"), QStringLiteral("closedLoopReference"),
                         tr("Mode 8: after every power-on, before closed loop can be switched "
                            "on. The motor turns."),
                         this)),
      m_enable(button(tr("4 Closed loop on\u2026"), QStringLiteral("closedLoopEnable"),
                      tr("Switch closed loop on and read it back; the drive ignores it without "
                         "the reference run since power-on"),
                      this)),
      m_disable(button(tr("Off"), QStringLiteral("closedLoopDisable"),
                       tr("Switch closed loop off and read it back"), this)),
      m_resetError(button(tr("Reset position error"), QStringLiteral("closedLoopResetError"),
                          tr("Clear the drive's position error; its position becomes the "
                             "encoder's (manual 5.14)"),
                          this)),
      m_motorData(new drives::OneLineLabel(this)), m_calibration(new drives::OneLineLabel(this)),
      m_referenceState(new drives::OneLineLabel(this)),
      m_closedLoop(new drives::OneLineLabel(this)), m_progressText(new drives::OneLineLabel(this)),
      m_message(new drives::OneLineLabel(this)), m_next(new drives::OneLineLabel(this)),
      m_progress(new QProgressBar(this))
{
    setObjectName(QStringLiteral("closedLoopPanel"));
    m_axis->setObjectName(QStringLiteral("closedLoopAxis"));
    m_axis->setToolTip(tr("The drive (axis) to commission"));
    m_direction->setObjectName(QStringLiteral("closedLoopDirection"));
    m_direction->addItem(tr("+ (d=1)"), 1);
    m_direction->addItem(tr("\u2212 (d=0)"), -1);
    m_direction->setToolTip(tr("Direction of the reference run ('d', manual 6.12)"));
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    m_progress->setTextVisible(false);
    m_progress->setMaximumHeight(m_progress->fontMetrics().height());
    buildLayout();
    connectParts();
    onModelChanged();
}

void ClosedLoopPanel::buildLayout()
{
    auto* grid = new QGridLayout(this);
    grid->addWidget(new QLabel(tr("Drive:"), this), 0, 0);
    grid->addWidget(m_axis, 0, 1);
    grid->addWidget(m_next, 0, 2, 1, 2);
    grid->addWidget(m_check, 1, 0, 1, 2);
    grid->addWidget(m_motorData, 1, 2, 1, 2);
    grid->addWidget(m_calibrate, 2, 0, 1, 2);
    grid->addWidget(m_calibration, 2, 2, 1, 2);
    grid->addWidget(m_reference, 3, 0);
    grid->addWidget(m_direction, 3, 1);
    grid->addWidget(m_referenceState, 3, 2, 1, 2);
    grid->addWidget(m_enable, 4, 0);
    grid->addWidget(m_disable, 4, 1);
    grid->addWidget(m_closedLoop, 4, 2, 1, 2);
    grid->addWidget(m_progress, 5, 0, 1, 2);
    grid->addWidget(m_progressText, 5, 2, 1, 2);
    grid->addWidget(m_resetError, 6, 0, 1, 2);
    grid->addWidget(m_message, 6, 2, 1, 2);
    grid->setColumnStretch(2, 1);
}

void ClosedLoopPanel::connectParts()
{
    m_poll.setInterval(kPollMs);
    connect(&m_poll, &QTimer::timeout, this, &ClosedLoopPanel::pollState);
    ControllerSession* session = m_context->session();
    connect(session, &ControllerSession::requestFinished, this, &ClosedLoopPanel::onResult);
    connect(session, &ControllerSession::linkStateChanged, this, &ClosedLoopPanel::onLinkState);
    connect(m_context, &MachineContext::modelChanged, this, &ClosedLoopPanel::onModelChanged);
    connect(m_axis, &QComboBox::currentIndexChanged, this, [this] {
        clearTexts();
        pollState();
    });
    connect(m_check, &QPushButton::clicked, this, &ClosedLoopPanel::check);
    connect(m_calibrate, &QPushButton::clicked, this, &ClosedLoopPanel::askCalibrate);
    connect(m_reference, &QPushButton::clicked, this, &ClosedLoopPanel::askReference);
    connect(m_enable, &QPushButton::clicked, this, &ClosedLoopPanel::askEnable);
    connect(m_disable, &QPushButton::clicked, this, &ClosedLoopPanel::disable);
    connect(m_resetError, &QPushButton::clicked, this, &ClosedLoopPanel::resetError);
}

QString ClosedLoopPanel::motorDataText() const
{
    return elided(m_motorData)->fullText();
}
QString ClosedLoopPanel::calibrationText() const
{
    return elided(m_calibration)->fullText();
}
QString ClosedLoopPanel::referenceText() const
{
    return elided(m_referenceState)->fullText();
}
QString ClosedLoopPanel::closedLoopText() const
{
    return elided(m_closedLoop)->fullText();
}
QString ClosedLoopPanel::progressText() const
{
    return elided(m_progressText)->fullText();
}
QString ClosedLoopPanel::messageText() const
{
    return elided(m_message)->fullText();
}
QString ClosedLoopPanel::nextStepText() const
{
    return elided(m_next)->fullText();
}

QVariantMap ClosedLoopPanel::axisArgs() const
{
    return {{cl::kAxis, m_axis->currentData().toString()}};
}

void ClosedLoopPanel::onModelChanged()
{
    const Capabilities caps = m_context->capabilities();
    setVisible(caps.closedLoop);
    const QSignalBlocker block(m_axis);
    m_axis->clear();
    for (Axis a : caps.axes)
        m_axis->addItem(m_context->controllerAxisName(a), axisName(a)); // data: the operation's
    clearTexts();
    updateEnabled();
}

void ClosedLoopPanel::onLinkState(LinkState state)
{
    if (state != LinkState::Connected) {
        // A run cannot outlive the link: the adapter has sent its stop and ends the request.
        m_poll.stop();
        m_progress->setRange(0, 1);
        if (state == LinkState::Disconnected)
            clearTexts(); // nothing read in a closed connection holds any more
    } else {
        onModelChanged(); // the axis map of this connection
        pollState();
    }
    updateEnabled();
}

void ClosedLoopPanel::clearTexts()
{
    m_motorDataFit.reset();
    m_state.clear();
    const QString unknown = tr("not checked in this connection");
    elided(m_motorData)->setFullText(unknown);
    elided(m_calibration)->setFullText({});
    elided(m_referenceState)->setFullText({});
    elided(m_closedLoop)->setFullText({});
    elided(m_progressText)->setFullText({});
    elided(m_message)->setFullText({});
    showNextStep();
}

void ClosedLoopPanel::updateEnabled()
{
    const bool idle = m_context->isConnected() && !m_pending && m_axis->count() > 0;
    m_axis->setEnabled(idle);
    m_direction->setEnabled(idle);
    m_check->setEnabled(idle);
    // Guided: a run only after a check found motor data that can work (8.6-8.8).
    m_calibrate->setEnabled(idle && m_motorDataFit.value_or(false));
    m_reference->setEnabled(idle && m_motorDataFit.value_or(false));
    m_enable->setEnabled(idle && m_motorDataFit.value_or(false));
    m_disable->setEnabled(idle);
    m_resetError->setEnabled(idle);
}

void ClosedLoopPanel::send(Step step, const QString& operation, const QVariantMap& extra)
{
    if (m_pending || !m_context->isConnected())
        return;
    QVariantMap args = axisArgs();
    for (auto it = extra.cbegin(); it != extra.cend(); ++it)
        args.insert(it.key(), it.value());
    m_step = step;
    elided(m_message)->setFullText({});
    m_pending = m_context->session()->modelOperation(operation, args);
    if (step == Step::Calibrate || step == Step::Reference) {
        m_progress->setRange(0, 0); // busy: the drive reports no percentage
        m_poll.start();
    }
    updateEnabled();
}

void ClosedLoopPanel::confirmThen(const QString& title, const QString& text,
                                  std::function<void()> go)
{
    dialogs::message(this, QMessageBox::Warning, title, text, QMessageBox::Ok | QMessageBox::Cancel,
                     QMessageBox::Cancel, [go = std::move(go)](QMessageBox::StandardButton chosen) {
                         if (chosen == QMessageBox::Ok)
                             go();
                     });
}

void ClosedLoopPanel::check()
{
    send(Step::Check, cl::kCheck);
}

void ClosedLoopPanel::askCalibrate()
{
    confirmThen(
        tr("Calibration run"),
        tr("The calibration run (mode 101) of axis %1 turns the motor. Let the shaft turn "
           "freely; STOP and PANIC end the run at once.\n\nManual 8.1: a calibration run is "
           "needed every time a motor is connected, even one of the same type. Pole pairs, "
           "encoder increments and revolutions must match the motor: otherwise closed loop can "
           "speed the motor up beyond its mechanical limits.\n\nStart the calibration run now?")
            .arg(m_axis->currentText()),
        [this] { send(Step::Calibrate, cl::kCalibrate); });
}

void ClosedLoopPanel::askReference()
{
    const int direction = m_direction->currentData().toInt();
    confirmThen(
        tr("Closed-loop reference run"),
        tr("The closed-loop reference run (mode 8) of axis %1 turns the motor in the "
           "direction %2 until the encoder's index mark. STOP and PANIC end it at once."
           "\n\nManual 8.1: closed loop can only be switched on after this run since "
           "the drive was switched on.\n\nStart the reference run now?")
            .arg(m_axis->currentText(), m_direction->currentText()),
        [this, direction] {
            send(Step::Reference, cl::kReference, {{operation::arg::kDirection, direction}});
        });
}

void ClosedLoopPanel::askEnable()
{
    confirmThen(tr("Closed loop on"),
                tr("ATTENTION (manual 8.1): if pole pairs or encoder data do not match the "
                   "motor, or this motor was never calibrated on this drive, closed loop can "
                   "speed the motor up beyond its mechanical limits.\n\nSwitch closed loop on "
                   "for axis %1?")
                    .arg(m_axis->currentText()),
                [this] {
                    send(Step::Enable, cl::kEnable, {{operation::arg::kOn, true}});
                });
}

void ClosedLoopPanel::disable()
{
    send(Step::Disable, cl::kEnable, {{operation::arg::kOn, false}});
}

void ClosedLoopPanel::resetError()
{
    // The drive's own operation (5.14 'D'): clears the error, position := encoder position.
    send(Step::ResetError, operation::kResetPositionError);
}

void ClosedLoopPanel::pollState()
{
    if (!m_context->isConnected() || m_stateRequest || m_axis->count() == 0 ||
        !m_context->capabilities().closedLoop)
        return;
    m_stateRequest = m_context->session()->modelOperation(cl::kState, axisArgs());
}

} // namespace stepdeck::ui
