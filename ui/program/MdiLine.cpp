#include "MdiLine.h"
#include "common/ElidedLabel.h"
#include "common/ReservedSize.h"
#include "machine/MachineContext.h"
#include "machine/MachineMdi.h"
#include "program/ProgramParser.h"
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace stepdeck::ui {

MdiLine::MdiLine(MachineContext* context, QWidget* parent)
    : QWidget(parent), m_context(context), m_mdi(context->mdi()), m_line(new QLineEdit(this)),
      m_run(new QPushButton(tr("Run line"), this)), m_modal(new QLabel(this)),
      m_result(new ElidedLabel(this))
{
    setObjectName(QStringLiteral("mdiLine"));
    m_line->setObjectName(QStringLiteral("mdiText"));
    m_line->setPlaceholderText(tr("G-code line, e.g. G0 X10 Y5 (Enter runs it, Up: the last)"));
    m_line->setMaxLength(program::ProgramParser::kMaxLineLength);
    m_line->setClearButtonEnabled(true);
    m_run->setToolTip(tr("Runs the line on the machine after the same check a program has"));
    m_modal->setToolTip(tr("The modal state the next line starts in (LinuxCNC's active "
                           "G-codes)"));
    m_modal->setForegroundRole(QPalette::PlaceholderText);
    // A new F never re-lays out the page: room for the longest state there is.
    reserveTextSize(m_modal, {QStringLiteral("G91 G20 G19 G61.1 G93 G43 F88888.888")});
    auto* label = new QLabel(tr("MDI:"), this);
    label->setBuddy(m_line);
    // The line, then its result in a row of its own (issue 47 item 10: beside the line, at
    // 1366x768, the result was cut to "Not done: …" and the reason lived in the tooltip). One
    // line high always: a result never re-flows the page.
    m_result->setObjectName(QStringLiteral("mdiResult"));
    auto* rows = new QVBoxLayout(this);
    rows->setContentsMargins(0, 0, 0, 0);
    rows->setSpacing(1);
    auto* row = new QHBoxLayout;
    row->addWidget(label);
    row->addWidget(m_line, 1);
    row->addWidget(m_run);
    row->addWidget(m_modal);
    rows->addLayout(row);
    rows->addWidget(m_result);
    m_line->installEventFilter(this);
    connect(m_line, &QLineEdit::returnPressed, this, &MdiLine::run);
    connect(m_run, &QPushButton::clicked, this, &MdiLine::run);
    connect(m_mdi, &MachineMdi::ended, this, &MdiLine::onEnded);
    connect(m_mdi, &MachineMdi::busyChanged, this, &MdiLine::updateState);
    connect(m_mdi, &MachineMdi::paused, this, [this](quint64 id, const QString& prompt) {
        if (id != m_pending)
            return;
        m_result->setText(prompt.isEmpty() ? tr("Holding: Resume goes on.")
                                           : tr("Holding: %1 (Resume goes on)").arg(prompt));
        updateState();
    });
    connect(context, &MachineContext::machineChanged, this, &MdiLine::updateState);
    updateState();
}

void MdiLine::run()
{
    if (m_pending != 0 && m_mdi->isPausedAtOperatorStop()) {
        m_result->setText(tr("Running: %1").arg(m_pendingText));
        m_mdi->resume(); // may end the line at once (an M0 on its own)
        updateState();
        return;
    }
    const QString text = m_line->text().trimmed();
    if (text.isEmpty())
        return;
    QString refusal;
    const quint64 id = m_mdi->runLine(text, &refusal);
    m_historyIndex = -1;
    if (id == 0) {
        m_result->setText(tr("Refused: %1").arg(refusal));
        return;
    }
    m_pending = id;
    m_pendingText = text;
    m_line->clear(); // the next line; Up brings this one back
    m_result->setText(tr("Checking, then running: %1").arg(text));
    updateState();
}

void MdiLine::onEnded(quint64 id, bool ok, const QString& message)
{
    if (id == 0 || id != m_pending)
        return;
    m_pending = 0;
    m_result->setText(ok ? tr("Done: %1").arg(m_pendingText)
                         : tr("Not done: %1 (%2)").arg(message, m_pendingText));
    updateState();
}

void MdiLine::updateState()
{
    const bool held = m_pending != 0 && m_mdi->isPausedAtOperatorStop();
    m_run->setText(held ? tr("Resume") : tr("Run line"));
    m_run->setEnabled(m_context->machine() && (held || !m_mdi->isBusy()));
    m_modal->setText(program::MdiSession::modalText(m_mdi->session().modal()));
}

bool MdiLine::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == m_line && event->type() == QEvent::KeyPress) {
        const int key = static_cast<QKeyEvent*>(event)->key();
        if (key == Qt::Key_Up || key == Qt::Key_Down) {
            browseHistory(key == Qt::Key_Up ? -1 : 1);
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

void MdiLine::browseHistory(int step)
{
    const QStringList history = m_mdi->session().history();
    if (history.isEmpty())
        return;
    if (m_historyIndex < 0) {
        if (step > 0)
            return;
        m_typed = m_line->text();
        m_historyIndex = int(history.size());
    }
    m_historyIndex += step;
    if (m_historyIndex >= history.size()) { // past the newest: the line being typed again
        m_historyIndex = -1;
        m_line->setText(m_typed);
        return;
    }
    m_historyIndex = qMax(0, m_historyIndex);
    m_line->setText(history.at(m_historyIndex));
}

QString MdiLine::resultText() const
{
    return m_result->text();
}

QString MdiLine::shownResultText() const
{
    return m_result->shownLines().join(QLatin1Char(' '));
}

QString MdiLine::modalText() const
{
    return m_modal->text();
}

} // namespace stepdeck::ui
