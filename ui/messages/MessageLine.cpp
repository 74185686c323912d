#include "MessageLine.h"
#include "common/ElidedLabel.h"
#include "common/IfChanged.h"
#include "messages/StatusMessages.h"
#include <QHBoxLayout>
#include <QToolButton>

namespace stepdeck::ui {

MessageLine::MessageLine(StatusMessages* messages, QWidget* parent)
    : QWidget(parent), m_messages(messages), m_label(new ElidedLabel(this)),
      m_button(new QToolButton(this))
{
    setObjectName(QStringLiteral("messageLine"));
    m_label->setObjectName(QStringLiteral("statusMessage"));
    m_label->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    m_button->setObjectName(QStringLiteral("messagesButton"));
    m_button->setFocusPolicy(Qt::NoFocus);
    m_button->setAutoRaise(true);
    m_button->setToolTip(tr("Open the message log: every message with its time"));
    // The button keeps the width of its longest text, so a new count moves nothing.
    m_button->setText(tr("Messages (%1)").arg(StatusMessages::kLogLimit));
    m_button->setFixedWidth(m_button->sizeHint().width());
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_label, 1);
    layout->addWidget(m_button);
    connect(m_button, &QToolButton::clicked, this, &MessageLine::logRequested);
    connect(messages, &StatusMessages::changed, this, &MessageLine::showCurrent);
    connect(messages, &StatusMessages::logged, this, [this] {
        if (!m_logOnScreen)
            m_unseen = qMin(m_unseen + 1, StatusMessages::kLogLimit);
        updateButton();
    });
    showCurrent();
    updateButton();
}

void MessageLine::setLogOnScreen(bool onScreen)
{
    m_logOnScreen = onScreen;
    if (onScreen)
        m_unseen = 0;
    updateButton();
}

void MessageLine::showCurrent()
{
    m_label->setText(m_messages->currentLine());
    setStyleSheetIfChanged(m_label, m_messages->currentSeverity() == StatusMessages::Severity::Error
                                        ? QStringLiteral("QLabel { color: #c62828; }")
                                        : QString());
}

void MessageLine::updateButton()
{
    m_button->setText(m_unseen > 0 ? tr("Messages (%1)").arg(m_unseen) : tr("Messages"));
}

} // namespace stepdeck::ui
