#include "SafetyBar.h"
#include "common/ElidedLabel.h"
#include "common/IfChanged.h"
#include "machine/MachineContext.h"
#include "protocols/Registry.h"
#include "safety/SafetyBanner.h"
#include <QAction>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

namespace stepdeck::ui {

namespace {
bool showsMotion(const MachineStatus& s)
{
    if (s.busy || s.anyMoving() || s.motionUnconfirmed)
        return true;
    for (const AxisStatus& a : s.axes) {
        if (a.jogging || a.commandedVelocity != 0.0)
            return true;
    }
    return false;
}
} // namespace

SafetyBar::SafetyBar(MachineContext* context, QAction* stop, QAction* panic, QAction* reference,
                     QWidget* parent)
    : QWidget(parent), m_context(context), m_stop(new QPushButton(this)),
      m_panic(new QPushButton(this)), m_reference(new QPushButton(this)),
      m_banner(new ElidedLabel(this)), m_noStop(new ElidedLabel(this))
{
    setObjectName(QStringLiteral("safetyBar"));
    m_stop->setObjectName(QStringLiteral("stopButton"));
    m_panic->setObjectName(QStringLiteral("panicButton"));
    m_reference->setText(tr("Reference all")); // it runs at once: no "…" (issue 16)
    for (QPushButton* b : {m_stop, m_panic}) {
        b->setFocusPolicy(Qt::NoFocus); // never steal focus from what the operator typed in
        b->setMinimumSize(140, 48);
    }
    m_stop->setStyleSheet(QStringLiteral(
        "QPushButton { background: #ffb300; color: #1a1a1a; border: 2px solid #c68400;"
        " border-radius: 6px; padding: 2px 10px; } QPushButton:pressed { background: #c68400; }"));
    m_panic->setStyleSheet(QStringLiteral(
        "QPushButton { background: #d32f2f; color: white; border: 2px solid #8e0000;"
        " border-radius: 6px; padding: 2px 10px; } QPushButton:pressed { background: #8e0000; }"));
    m_reference->setFocusPolicy(Qt::NoFocus);
    // Offered or not, the button keeps its room: the banner below never moves.
    QSizePolicy keep = m_reference->sizePolicy();
    keep.setRetainSizeWhenHidden(true);
    m_reference->setSizePolicy(keep);
    // Banner and note span the whole width and reserve the room of their longest text: a new
    // state never moves the jog pad below them, and safety texts are never cut (issue 16).
    m_banner->setObjectName(QStringLiteral("safetyBanner"));
    m_banner->setMargin(6);
    m_banner->setReservedTexts(SafetyBanner::possibleTexts());
    m_noStop->setObjectName(QStringLiteral("noStopCommandNote"));
    m_noStop->setMargin(4);
    m_noStop->setReservedTexts({Controller::noStopCommandText()});
    m_noStop->setStyleSheet(QStringLiteral("QLabel { background:#ffcdd2; color:#8e0000; "
                                           "font-weight:bold; border-radius:4px; }"));

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(6, 6, 6, 6);
    layout->setSpacing(4);
    auto* buttons = new QHBoxLayout;
    m_buttonRow = buttons;
    buttons->addWidget(m_stop);
    buttons->addWidget(m_panic);
    buttons->addStretch(1);
    buttons->addWidget(m_reference, 0, Qt::AlignBottom);
    layout->addLayout(buttons);
    layout->addWidget(m_noStop);
    layout->addWidget(m_banner);

    connect(m_stop, &QPushButton::clicked, stop, &QAction::trigger);
    connect(m_panic, &QPushButton::clicked, panic, &QAction::trigger);
    connect(m_reference, &QPushButton::clicked, reference, &QAction::trigger);

    ControllerSession* session = context->session();
    connect(session, &ControllerSession::statusChanged, this, &SafetyBar::onStatus);
    connect(session, &ControllerSession::linkStateChanged, this, &SafetyBar::onLinkState);
    connect(context, &MachineContext::panicTriggered, this, [this] {
        m_positionsLost = true;
        m_hadReferenced = true;
        m_hostPanicSent = true;
        m_sawPanic = false; // statuses from before the panic may still arrive
        refresh();
    });
    connect(context, &MachineContext::modelChanged, this, &SafetyBar::applyCapabilities);
    connect(context, &MachineContext::machineStatusChanged, this, &SafetyBar::refresh);
    connect(session, &ControllerSession::linkStateChanged, this, &SafetyBar::applyCapabilities);
    applyCapabilities();
    refresh();
}

void SafetyBar::applyCapabilities()
{
    const ModelInfo* model = m_context->model();
    showCapabilities(m_context->capabilities(), model ? model->presentation : ModelPresentation{});
}

void SafetyBar::showCapabilities(const Capabilities& caps, const ModelPresentation& presentation)
{
    const bool canStop = caps.stopCommand;
    // Two-line labels in a smaller type, so both buttons fit beside each other at 1366x768.
    for (QPushButton* b : {m_stop, m_panic}) {
        QFont f = font();
        f.setBold(true);
        f.setPointSizeF(f.pointSizeF() * (canStop ? 1.35 : 1.1));
        b->setFont(f);
    }
    m_stop->setText(canStop ? tr("STOP  (Esc)") : tr("STOP  (Esc)\ndoes not stop the controller"));
    m_panic->setText(canStop ? tr("PANIC  (F1)") : tr("PANIC  (F1)\ndoes not stop the controller"));
    m_stop->setToolTip(canStop ? tr("Ramped stop of all motion")
                               : tr("Ends every jog input and the host's queued work; %1")
                                     .arg(Controller::noStopCommandText()));
    m_panic->setToolTip(canStop ? tr("Immediate stop without ramp: steps are lost, the machine "
                                     "must be referenced afterwards")
                                : tr("Ends every jog input and the host's queued work; %1")
                                      .arg(Controller::noStopCommandText()));
    m_noStop->setText(presentation.noStopNote ? presentation.noStopNote()
                                              : Controller::noStopCommandText());
    m_noStop->setToolTip(presentation.noStopNoteDetail ? presentation.noStopNoteDetail()
                                                       : QString());
    m_noStop->setVisible(!canStop);
}

QString SafetyBar::bannerText() const
{
    return m_banner->text();
}

QString SafetyBar::bannerSeverity() const
{
    return m_banner->property("severity").toString();
}

void SafetyBar::onStatus(const MachineStatus& status)
{
    if (m_context->isConnected()) {
        for (const AxisStatus& a : status.axes)
            m_hadReferenced = m_hadReferenced || a.referenced;
        m_lastShowedMotion = showsMotion(status);
        if (!m_lastShowedMotion)
            m_movingWhenLinkEnded = false; // the device itself reports standstill
        if (m_sawPanic && !status.panic)
            m_hostPanicSent = false; // a new motion cleared the panic
        m_sawPanic = status.panic;
    }
    refresh();
}

void SafetyBar::onLinkState(LinkState state)
{
    // A reconnect loses what was referenced; a first connection has nothing to lose.
    if ((state == LinkState::Connecting || state == LinkState::Lost) && m_hadReferenced)
        m_positionsLost = true;
    if (state == LinkState::Lost || state == LinkState::Disconnected)
        m_movingWhenLinkEnded = m_movingWhenLinkEnded || m_lastShowedMotion;
    if (state != LinkState::Connected) {
        m_lastShowedMotion = false;
        m_hostPanicSent = false;
    }
    refresh();
}

void SafetyBar::setJob(program::RunState state, int line)
{
    if (state == m_job && line == m_jobLine)
        return;
    m_job = state;
    m_jobLine = line;
    refresh();
}

void SafetyBar::refresh()
{
    // With a machine open the banner speaks of all of it, not of the controller the pages show.
    LinkState link = LinkState::Disconnected;
    const MachineStatus status = m_context->machineWideStatus(&link);
    const machine::PositionKnowledge positions = m_context->positionKnowledge();
    if (positions == machine::PositionKnowledge::Referenced && link == LinkState::Connected)
        m_positionsLost = false;

    SafetyBannerInput in;
    in.link = link;
    in.status = status;
    in.positions = positions;
    in.positionsLost = m_positionsLost;
    in.movingWhenLinkEnded = m_movingWhenLinkEnded;
    in.hostPanicSent = m_hostPanicSent;
    in.job = m_job;
    in.jobLine = m_jobLine;
    const SafetyBannerText banner = SafetyBanner::compute(in);
    static const QMap<QString, QString> colours{
        {QStringLiteral("fault"), QStringLiteral("background:#ffcdd2; color:#8e0000;")},
        {QStringLiteral("warning"), QStringLiteral("background:#ffe082; color:#4e3400;")},
        {QStringLiteral("ok"), QStringLiteral("background:#c8e6c9; color:#1b5e20;")},
        {QStringLiteral("idle"), QStringLiteral("background:#eceff1; color:#37474f;")},
        {QStringLiteral("job"), QStringLiteral("background:#bbdefb; color:#0d47a1;")},
    };
    m_banner->setText(banner.text);
    setStyleSheetIfChanged(m_banner,
                           QStringLiteral("QLabel { %1 border-radius: 4px; font-weight: bold; }")
                               .arg(colours.value(banner.severity)));
    m_banner->setProperty("severity", banner.severity);
    m_reference->setVisible(banner.offerReference);
}

void SafetyBar::addRowButton(QWidget* button)
{
    m_buttonRow->insertWidget(m_buttonRow->indexOf(m_reference), button, 0, Qt::AlignBottom);
}

} // namespace stepdeck::ui
