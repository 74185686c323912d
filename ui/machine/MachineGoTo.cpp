#include "MachineGoTo.h"
#include "common/ElidedLabel.h"
#include "controller/ControllerSession.h"
#include "machine/Machine.h"
#include "machine/MachineContext.h"
#include "machine/MachineMdi.h"
#include "machine/MachineWorkOffsets.h"
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace stepdeck::ui {

MachineGoTo::MachineGoTo(MachineContext* context, MachineWorkOffsets* offsets, QWidget* parent)
    : QWidget(parent), m_context(context), m_offsets(offsets), m_label(new QLabel(this)),
      m_axis(new QComboBox(this)), m_target(new QDoubleSpinBox(this)),
      m_go(new QPushButton(tr("Go to"), this)), m_result(new ElidedLabel(this))
{
    setObjectName(QStringLiteral("machineGoTo"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* row = new QHBoxLayout;
    // As wide as its longer text: switching to work coordinates moves nothing in the row.
    m_label->setMinimumWidth(qMax(m_label->fontMetrics().horizontalAdvance(tr("Go to:")),
                                  m_label->fontMetrics().horizontalAdvance(tr("Go to (work):"))));
    row->addWidget(m_label);
    row->addWidget(m_axis);
    row->addWidget(m_target, 1);
    row->addWidget(m_go);
    layout->addLayout(row);
    layout->addWidget(m_result);
    m_target->setRange(-1e6, 1e6);
    // Its width from the row, not from the range and unit: the widest value with the longest
    // unit (German "Einheiten") would widen the read-out's page (tst_layoutholdsstill).
    m_target->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    m_target->setMinimumWidth(m_target->fontMetrics().averageCharWidth() * 14 + 36);
    m_go->setFocusPolicy(Qt::NoFocus);
    // Enter in the target field goes there, like the button (issue 16).
    m_target->installEventFilter(this);
    connect(m_go, &QPushButton::clicked, this, &MachineGoTo::go);
    connect(m_axis, &QComboBox::currentIndexChanged, this, &MachineGoTo::updateUnit);
    connect(context, &MachineContext::machineChanged, this, &MachineGoTo::rebuild);
    connect(offsets, &MachineWorkOffsets::changed, this, &MachineGoTo::updateUnit);
    connect(context->mdi(), &MachineMdi::started, this, [this](quint64 id) {
        if (id != m_pending)
            return;
        m_moveStarted = true;
        m_result->setText(m_movingText);
    });
    connect(context->mdi(), &MachineMdi::ended, this, &MachineGoTo::onEnded);
    rebuild();
}

void MachineGoTo::rebuild()
{
    m_axis->clear();
    m_pending = 0;
    disconnect(m_confirm);
    m_go->setEnabled(true);
    m_result->clear();
    machine::Machine* m = m_context->machine();
    if (!m)
        return;
    for (const machine::MachineAxis& a : m->description().axes)
        m_axis->addItem(a.name, a.name);
    updateUnit();
}

void MachineGoTo::updateUnit()
{
    const machine::Machine* m = m_context->machine();
    const machine::MachineAxis* a =
        m ? m->description().axis(m_axis->currentData().toString()) : nullptr;
    const bool work = a && m_offsets->hasOffset(a->name);
    m_label->setText(work ? tr("Go to (work):") : tr("Go to:"));
    m_target->setToolTip(work ? tr("Target in work coordinates (the work zero of the axis is "
                                   "subtracted from machine positions); the axis must be "
                                   "referenced")
                              : tr("Absolute target in the axis' unit; the axis must be "
                                   "referenced"));
    if (!a)
        return;
    const bool steps = a->unit == machine::AxisUnit::Step;
    m_target->setDecimals(steps ? 0 : 3);
    m_target->setSuffix(QLatin1Char(' ') + m_context->axisUnitName(*a)); // as the read-out
}

bool MachineGoTo::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == m_target && event->type() == QEvent::KeyPress) {
        const int key = static_cast<QKeyEvent*>(event)->key();
        if (key == Qt::Key_Return || key == Qt::Key_Enter) {
            go();
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

void MachineGoTo::go()
{
    machine::Machine* m = m_context->machine();
    if (!m || m_axis->currentIndex() < 0)
        return;
    if (m_pending != 0) { // one go-to at a time: the next waits for the arrival of this one
        m_result->setText(tr("Go-to refused: the last go-to is still moving."));
        return;
    }
    const QString axis = m_axis->currentData().toString();
    const machine::MachineAxis* a = m->description().axis(axis);
    if (!a)
        return;
    const bool steps = a->unit == machine::AxisUnit::Step;
    // A G0 of its own in G-code's defaults (G90, G21: millimetre axes take mm, rotary axes
    // degrees, step axes steps), in the active coordinate system, through the same check and
    // path as a program's G0 (issue 30): refused as a whole before anything is sent when the
    // axis is not referenced, a controller not connected or the target outside the soft limits.
    const QString target = QString::number(m_target->value(), 'f', steps ? 0 : 3);
    QString refusal;
    m_moveStarted = false;
    m_pending = m_context->mdi()->runOwnLine(QStringLiteral("G0 %1%2").arg(axis, target), &refusal);
    m_pendingAxis = axis;
    // The soft limits and the arrival are judged in machine coordinates.
    m_pendingTarget = m_offsets->toMachine(axis, m_target->value());
    const QString machineTarget = steps ? QString::number(qRound64(m_pendingTarget))
                                        : QString::number(m_pendingTarget, 'f', 3);
    m_go->setEnabled(m_pending == 0);
    m_movingText = m_offsets->hasOffset(axis)
                       ? tr("Moving %1 to %2 (work; machine %3)\u2026")
                             .arg(axis, m_target->text(), machineTarget)
                       : tr("Moving %1 to %2\u2026").arg(axis, m_target->text());
    // Nothing moves before the check has passed (MachineMdi::started).
    m_result->setText(!m_pending
                          ? tr("Go-to refused: %1").arg(refusal)
                          : tr("Checking the go-to of %1 to %2\u2026").arg(axis, m_target->text()));
}

void MachineGoTo::onEnded(quint64 id, bool ok, const QString& message)
{
    if (id == 0 || id != m_pending)
        return;
    m_pending = 0;
    m_go->setEnabled(true);
    if (!ok) {
        // The check's refusal (nothing sent) or the run's end short of the target.
        m_result->setText(m_moveStarted ? tr("Go-to failed: %1").arg(message)
                                        : tr("Go-to refused: %1").arg(message));
        return;
    }
    // The run's move ended with the axis standing. "Arrived" only where a status read asked
    // for after that counts it at the target: a STOP ends a move short of it, and a board
    // that reports no position (the E-LAB) corrects its count only after the stop
    // (RequestRelPosition), ahead of that read.
    const machine::Machine* m = m_context->machine();
    const machine::MachineAxis* a = m ? m->description().axis(m_pendingAxis) : nullptr;
    ControllerSession* session = a ? m->session(a->controller) : nullptr;
    if (!session)
        return;
    m_result->setText(tr("%1 stands: reading its position\u2026").arg(a->name));
    disconnect(m_confirm);
    const RequestId read = session->refreshStatus();
    m_confirm = connect(session, &ControllerSession::requestFinished, this,
                        [this, read](const CommandResult& r) {
                            if (r.id != read)
                                return;
                            disconnect(m_confirm);
                            judgeArrival(r.ok());
                        });
}

void MachineGoTo::judgeArrival(bool read)
{
    const machine::Machine* m = m_context->machine();
    const machine::MachineAxis* a = m ? m->description().axis(m_pendingAxis) : nullptr;
    if (!a)
        return;
    const machine::MachineAxisStatus status = m->axisStatus(*a);
    const bool atTarget = read && status.known != machine::PositionKnowledge::Unknown &&
                          qAbs(status.position - m_pendingTarget) * a->stepsPerUnit < 0.5;
    m_result->setText(atTarget ? tr("%1 arrived.").arg(a->name)
                      : !read  ? tr("%1 stands; its position could not be read.").arg(a->name)
                               : tr("%1 stopped at %2 before its target %3.")
                                    .arg(a->name, QString::number(status.position, 'f', 3),
                                         QString::number(m_pendingTarget, 'f', 3)));
}

QString MachineGoTo::labelText() const
{
    return m_label->text();
}

QString MachineGoTo::resultText() const
{
    return m_result->text();
}

} // namespace stepdeck::ui
