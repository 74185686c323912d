#include "SafetyBar.h"
#include "main/MachineContext.h"
#include <QAction>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

namespace stepdeck::ui {

SafetyBar::SafetyBar(MachineContext* context, QAction* stop, QAction* panic, QAction* reference,
                     QWidget* parent)
    : QWidget(parent), m_context(context), m_stop(new QPushButton(this)),
      m_panic(new QPushButton(this)), m_reference(new QPushButton(this)), m_banner(new QLabel(this))
{
    setObjectName(QStringLiteral("safetyBar"));
    m_stop->setObjectName(QStringLiteral("stopButton"));
    m_panic->setObjectName(QStringLiteral("panicButton"));
    m_stop->setText(tr("STOP  (Esc)"));
    m_panic->setText(tr("PANIC  (F1)"));
    m_stop->setToolTip(tr("Ramped stop of all motion"));
    m_panic->setToolTip(tr("Immediate stop without ramp: steps are lost, the machine must be "
                           "referenced afterwards"));
    m_reference->setText(tr("Reference all\u2026"));
    for (QPushButton* b : {m_stop, m_panic}) {
        b->setFocusPolicy(Qt::NoFocus); // never steal focus from what the operator typed in
        b->setMinimumSize(150, 48);
        QFont f = b->font();
        f.setBold(true);
        f.setPointSizeF(f.pointSizeF() * 1.35);
        b->setFont(f);
    }
    m_stop->setStyleSheet(QStringLiteral(
        "QPushButton { background: #ffb300; color: #1a1a1a; border: 2px solid #c68400;"
        " border-radius: 6px; } QPushButton:pressed { background: #c68400; }"));
    m_panic->setStyleSheet(
        QStringLiteral("QPushButton { background: #d32f2f; color: white; border: 2px solid #8e0000;"
                       " border-radius: 6px; } QPushButton:pressed { background: #8e0000; }"));
    m_reference->setFocusPolicy(Qt::NoFocus);
    m_banner->setObjectName(QStringLiteral("safetyBanner"));
    m_banner->setWordWrap(true);
    m_banner->setMinimumHeight(40);
    m_banner->setMargin(6);

    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(6, 6, 6, 6);
    layout->addWidget(m_stop);
    layout->addWidget(m_panic);
    auto* right = new QVBoxLayout;
    right->setSpacing(4);
    right->addWidget(m_banner, 1);
    auto* referenceRow = new QHBoxLayout;
    referenceRow->addStretch(1);
    referenceRow->addWidget(m_reference);
    right->addLayout(referenceRow);
    layout->addLayout(right, 1);

    connect(m_stop, &QPushButton::clicked, stop, &QAction::trigger);
    connect(m_panic, &QPushButton::clicked, panic, &QAction::trigger);
    connect(m_reference, &QPushButton::clicked, reference, &QAction::trigger);

    ControllerSession* session = context->session();
    connect(session, &ControllerSession::statusChanged, this, &SafetyBar::refresh);
    connect(session, &ControllerSession::linkStateChanged, this, [this](LinkState state) {
        if (state == LinkState::Connecting || state == LinkState::Lost)
            m_positionsLost = true; // reconnect: nothing is referenced any more
        refresh();
    });
    connect(context, &MachineContext::panicTriggered, this, [this] {
        m_positionsLost = true;
        refresh();
    });
    refresh();
}

QString SafetyBar::bannerText() const
{
    return m_banner->text();
}

void SafetyBar::refresh()
{
    const MachineStatus& status = m_context->status();
    bool allReferenced = !status.axes.isEmpty();
    for (const AxisStatus& axis : status.axes)
        allReferenced = allReferenced && axis.referenced;
    if (allReferenced)
        m_positionsLost = false;

    QString text;
    QString style;
    bool offerReference = false;
    if (!m_context->isConnected()) {
        text = m_context->session()->linkState() == LinkState::Lost
                   ? tr("Link lost: motion stopped by the controller's own safety, positions are "
                        "unknown. Reconnect, then reference all axes.")
                   : tr("Not connected.");
        style = m_context->session()->linkState() == LinkState::Lost ? QStringLiteral("fault")
                                                                     : QStringLiteral("idle");
    } else if (status.panic) {
        text = tr("EMERGENCY STOP active: positions are lost. Release the emergency stop, then "
                  "reference all axes.");
        style = QStringLiteral("fault");
    } else if (m_positionsLost) {
        text = tr("Positions are lost (panic stop or reconnect). Reference the machine before "
                  "any absolute move.");
        style = QStringLiteral("fault");
        offerReference = true;
    } else if (!allReferenced) {
        text = tr("Not referenced: positions are unknown until the axes are referenced.");
        style = QStringLiteral("warning");
        offerReference = true;
    } else {
        text = tr("Ready: all axes referenced.");
        style = QStringLiteral("ok");
    }
    static const QMap<QString, QString> colours{
        {QStringLiteral("fault"), QStringLiteral("background:#ffcdd2; color:#8e0000;")},
        {QStringLiteral("warning"), QStringLiteral("background:#ffe082; color:#4e3400;")},
        {QStringLiteral("ok"), QStringLiteral("background:#c8e6c9; color:#1b5e20;")},
        {QStringLiteral("idle"), QStringLiteral("background:#eceff1; color:#37474f;")},
    };
    m_banner->setText(text);
    m_banner->setStyleSheet(QStringLiteral("QLabel { %1 border-radius: 4px; font-weight: bold; }")
                                .arg(colours.value(style)));
    m_banner->setProperty("severity", style);
    m_reference->setVisible(offerReference);
}

} // namespace stepdeck::ui
