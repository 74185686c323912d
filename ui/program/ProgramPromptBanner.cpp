#include "ProgramPromptBanner.h"
#include "common/ElidedLabel.h"
#include <QHBoxLayout>
#include <QPushButton>

namespace stepdeck::ui {

ProgramPromptBanner::ProgramPromptBanner(QWidget* parent)
    : QWidget(parent), m_text(new ElidedLabel(this)), m_resume(new QPushButton(tr("Resume"), this)),
      m_keepZ(new QPushButton(tr("Keep Z"), this))
{
    setObjectName(QStringLiteral("programPromptBanner"));
    m_text->setObjectName(QStringLiteral("programPrompt"));
    m_resume->setObjectName(QStringLiteral("programPromptResume"));
    m_keepZ->setObjectName(QStringLiteral("programPromptKeepZ"));
    m_keepZ->setToolTip(tr("Go on with the work Z as it is: only when the tool in the spindle is "
                           "the one Z was set for. Another tool needs its touch-off (Zero Z)."));
    m_keepZ->hide();
    // The button's room stays when it is hidden: the prompt's arrival moves nothing.
    QSizePolicy keep = m_resume->sizePolicy();
    keep.setRetainSizeWhenHidden(true);
    m_resume->setSizePolicy(keep);
    auto* h = new QHBoxLayout(this);
    h->setContentsMargins(4, 2, 4, 2);
    h->addWidget(m_text, 1);
    h->addWidget(m_keepZ);
    h->addWidget(m_resume);
    setAttribute(Qt::WA_StyledBackground); // the prompt's background (style sheet)
    connect(m_resume, &QPushButton::clicked, this, &ProgramPromptBanner::resumeRequested);
    connect(m_keepZ, &QPushButton::clicked, this, &ProgramPromptBanner::keepZRequested);
    clearPrompt();
}

void ProgramPromptBanner::showPrompt(int line, const QString& prompt)
{
    m_showing = true;
    // The line, not a word: the hold may be an M0, an M1 or a tool change (M6), and the
    // prompt says which ("Load tool 2").
    m_text->setText(prompt.isEmpty()
                        ? tr("Line %1: the program holds. Resume when ready.").arg(line)
                        : tr("Line %1: %2").arg(line).arg(prompt));
    setStyleSheet(QStringLiteral("#programPromptBanner { background: #fff3c4; }"
                                 "#programPrompt { font-weight: bold; }"));
    m_resume->show();
}

void ProgramPromptBanner::setStatus(const QString& text)
{
    m_status = text;
    if (!m_showing)
        m_text->setText(text);
}

void ProgramPromptBanner::clearPrompt()
{
    m_showing = false;
    m_text->setText(m_status);
    setStyleSheet(QString());
    m_resume->hide();
    m_keepZ->hide();
}

void ProgramPromptBanner::showKeepZ(bool shown)
{
    m_keepZ->setVisible(shown && m_showing);
}

QString ProgramPromptBanner::text() const
{
    return m_text->text();
}

} // namespace stepdeck::ui
