#include "ProgramCheckStatus.h"
#include "common/ElidedLabel.h"
#include <QHBoxLayout>
#include <QProgressBar>
#include <QPushButton>
#include <QTimer>

namespace stepdeck::ui {

ProgramCheckStatus::ProgramCheckStatus(ElidedLabel* result, int progressSteps, QWidget* parent)
    : QStackedWidget(parent), m_progress(new QProgressBar(this)),
      m_cancel(new QPushButton(tr("Cancel"), this)), m_check(new QPushButton(tr("Check"), this)),
      m_delay(new QTimer(this))
{
    m_progress->setObjectName(QStringLiteral("programCheckProgress"));
    m_progress->setRange(0, progressSteps);
    m_progress->setFormat(tr("Checking: %p %"));
    m_cancel->setObjectName(QStringLiteral("programCancelCheck"));
    m_check->setObjectName(QStringLiteral("programCheckNow"));
    m_check->setToolTip(tr("Check the program against the machine now"));
    auto* resultPage = new QWidget(this);
    auto* h = new QHBoxLayout(resultPage);
    h->setContentsMargins(0, 0, 0, 0);
    h->addWidget(result, 1);
    h->addWidget(m_check);
    auto* runningPage = new QWidget(this);
    auto* r = new QHBoxLayout(runningPage);
    r->setContentsMargins(0, 0, 0, 0);
    r->addWidget(m_progress, 1);
    r->addWidget(m_cancel);
    addWidget(resultPage);
    addWidget(runningPage);
    m_delay->setSingleShot(true);
    m_delay->setInterval(kDefaultDelayMs);
    connect(m_delay, &QTimer::timeout, this, [this] { setCurrentIndex(1); });
    connect(m_check, &QPushButton::clicked, this, &ProgramCheckStatus::checkRequested);
    connect(m_cancel, &QPushButton::clicked, this, &ProgramCheckStatus::cancelRequested);
}

void ProgramCheckStatus::started()
{
    m_progress->setValue(0);
    if (m_delay->interval() <= 0)
        setCurrentIndex(1); // no delay: at once, not at the next turn of the event loop
    else
        m_delay->start();
}

void ProgramCheckStatus::finished()
{
    m_delay->stop();
    setCurrentIndex(0);
}

void ProgramCheckStatus::setProgress(int step)
{
    m_progress->setValue(step);
}

void ProgramCheckStatus::setDelay(int ms)
{
    m_delay->setInterval(ms);
}

} // namespace stepdeck::ui
