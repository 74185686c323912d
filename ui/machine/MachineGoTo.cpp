#include "MachineGoTo.h"
#include "common/ElidedLabel.h"
#include "controller/ControllerSession.h"
#include "machine/Machine.h"
#include "machine/MachineContext.h"
#include "machine/MachineMdi.h"
#include "program/MachineWorkOffsets.h"
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace stepdeck::ui {

namespace {
constexpr int kColumns = 2; // axis targets side by side: two fit the Position dock at 1366 px

QString axisValue(double value, bool steps)
{
    return steps ? QString::number(qRound64(value)) : QString::number(value, 'f', 3);
}
} // namespace

MachineGoTo::MachineGoTo(MachineContext* context, program::MachineWorkOffsets* offsets,
                         QWidget* parent)
    : QWidget(parent), m_context(context), m_offsets(offsets), m_label(new QLabel(this)),
      m_grid(new QGridLayout), m_go(new QPushButton(tr("Go to"), this)),
      m_result(new ElidedLabel(this))
{
    setObjectName(QStringLiteral("machineGoTo"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* row = new QHBoxLayout;
    row->addWidget(m_label);
    row->addStretch(1);
    row->addWidget(m_go);
    layout->addLayout(row);
    m_grid->setContentsMargins(0, 0, 0, 0);
    for (int c = 0; c < kColumns; ++c)
        m_grid->setColumnStretch(2 * c + 1, 1);
    layout->addLayout(m_grid);
    layout->addWidget(m_result);
    m_go->setFocusPolicy(Qt::NoFocus);
    m_go->setToolTip(tr("The checked axes go together, in one rapid move (G0)"));
    connect(m_go, &QPushButton::clicked, this, &MachineGoTo::go);
    connect(context, &MachineContext::machineChanged, this, &MachineGoTo::rebuild);
    connect(offsets, &program::MachineWorkOffsets::changed, this, &MachineGoTo::updateLabel);
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
    for (const Row& r : std::as_const(m_rows)) {
        delete r.check;
        delete r.target;
    }
    m_rows.clear();
    m_pending = 0;
    m_pendingAxes.clear();
    for (const QMetaObject::Connection& c : std::as_const(m_confirm))
        disconnect(c);
    m_confirm.clear();
    m_reads.clear();
    m_go->setEnabled(true);
    m_result->clear();
    machine::Machine* m = m_context->machine();
    const QList<machine::MachineAxis> axes =
        m ? m->description().axes : QList<machine::MachineAxis>();
    for (const machine::MachineAxis& a : axes) {
        Row r{a.name, new QCheckBox(a.name, this), new QDoubleSpinBox(this)};
        r.check->setObjectName(QStringLiteral("goToCheck_") + a.name);
        r.check->setToolTip(tr("Axis %1 goes with the others checked").arg(a.name));
        r.target->setObjectName(QStringLiteral("goToTarget_") + a.name);
        r.target->setRange(-1e6, 1e6);
        // Its width from the grid, not from the range and unit: the widest value with the
        // longest unit (German "Einheiten") would widen the read-out's page.
        r.target->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
        r.target->setMinimumWidth(r.target->fontMetrics().averageCharWidth() * 12 + 36);
        r.target->installEventFilter(this);
        const int i = int(m_rows.size());
        m_grid->addWidget(r.check, i / kColumns, 2 * (i % kColumns));
        m_grid->addWidget(r.target, i / kColumns, 2 * (i % kColumns) + 1);
        connect(r.check, &QCheckBox::toggled, this, &MachineGoTo::updateLabel);
        m_rows.append(r);
    }
    if (!m_rows.isEmpty())
        m_rows.first().check->setChecked(true); // one axis at first, as a single go-to
    updateUnits();
    updateLabel();
}

void MachineGoTo::updateUnits()
{
    const machine::Machine* m = m_context->machine();
    for (const Row& r : std::as_const(m_rows)) {
        const machine::MachineAxis* a = m ? m->description().axis(r.axis) : nullptr;
        if (!a)
            continue;
        const bool steps = a->unit == machine::AxisUnit::Step;
        r.target->setDecimals(steps ? 0 : 3);
        r.target->setSuffix(QLatin1Char(' ') + m_context->axisUnitName(*a)); // as the read-out
    }
}

void MachineGoTo::updateLabel()
{
    bool work = false;
    for (const Row& r : std::as_const(m_rows)) {
        const bool hasOffset = m_offsets->hasOffset(r.axis);
        work = work || (hasOffset && r.check->isChecked());
        r.target->setToolTip(hasOffset ? tr("Target of %1 in work coordinates (its work zero "
                                            "is subtracted from machine positions); the axis "
                                            "must be referenced")
                                             .arg(r.axis)
                                       : tr("Absolute target of %1 in its unit; the axis must "
                                            "be referenced")
                                             .arg(r.axis));
    }
    m_label->setText(work ? tr("Go to (work):") : tr("Go to:"));
}

QCheckBox* MachineGoTo::axisCheck(const QString& axis) const
{
    for (const Row& r : m_rows) {
        if (r.axis == axis)
            return r.check;
    }
    return nullptr;
}

QDoubleSpinBox* MachineGoTo::targetBox(const QString& axis) const
{
    for (const Row& r : m_rows) {
        if (r.axis == axis)
            return r.target;
    }
    return nullptr;
}

QStringList MachineGoTo::checkedAxes() const
{
    QStringList out;
    for (const Row& r : m_rows) {
        if (r.check->isChecked())
            out << r.axis;
    }
    return out;
}

void MachineGoTo::choose(const QStringList& axes)
{
    for (const Row& r : std::as_const(m_rows))
        r.check->setChecked(axes.contains(r.axis));
}

// A target changed by hand (a digit, a sign, the arrows, the wheel) says its axis is to go;
// a value set by the program does not.
bool MachineGoTo::eventFilter(QObject* watched, QEvent* event)
{
    auto* box = qobject_cast<QDoubleSpinBox*>(watched);
    if (!box)
        return QWidget::eventFilter(watched, event);
    QCheckBox* check = nullptr;
    for (const Row& r : std::as_const(m_rows))
        check = r.target == box ? r.check : check;
    if (event->type() == QEvent::KeyPress) {
        const auto* key = static_cast<QKeyEvent*>(event);
        if (key->key() == Qt::Key_Return || key->key() == Qt::Key_Enter) {
            go();
            return true;
        }
        static const QList<int> editing{Qt::Key_Up,       Qt::Key_Down,      Qt::Key_PageUp,
                                        Qt::Key_PageDown, Qt::Key_Backspace, Qt::Key_Delete};
        const QString text = key->text();
        if (check && (editing.contains(key->key()) ||
                      (!text.isEmpty() &&
                       (text.at(0).isDigit() || QStringLiteral("+-.,").contains(text.at(0))))))
            check->setChecked(true);
    } else if (event->type() == QEvent::Wheel && check) {
        check->setChecked(true);
    }
    return QWidget::eventFilter(watched, event);
}

QString MachineGoTo::targetsText(bool withMachine) const
{
    const machine::Machine* m = m_context->machine();
    QStringList parts;
    for (const Pending& p : m_pendingAxes) {
        const QDoubleSpinBox* box = targetBox(p.axis);
        const machine::MachineAxis* a = m ? m->description().axis(p.axis) : nullptr;
        if (!box || !a)
            continue;
        const QString machineTarget =
            axisValue(p.machineTarget, a->unit == machine::AxisUnit::Step);
        parts << (withMachine && m_offsets->hasOffset(p.axis)
                      ? tr("%1 to %2 (work; machine %3)").arg(p.axis, box->text(), machineTarget)
                      : tr("%1 to %2").arg(p.axis, box->text()));
    }
    return parts.join(QStringLiteral(", "));
}

void MachineGoTo::go()
{
    machine::Machine* m = m_context->machine();
    if (!m || m_rows.isEmpty())
        return;
    if (m_pending != 0) { // one go-to at a time: the next waits for the arrival of this one
        m_result->setText(tr("Go-to refused: the last go-to is still moving."));
        return;
    }
    const QStringList axes = checkedAxes();
    if (axes.isEmpty()) {
        m_result->setText(tr("Go-to refused: no axis is checked."));
        return;
    }
    // One G0 in G-code's defaults (G90, G21: millimetre axes take mm, rotary axes degrees, step
    // axes steps), in the active coordinate system, through the same check and path as a
    // program's G0 (issue 30): refused as a whole before anything is sent when an axis is not
    // referenced, a controller not connected or a target outside the soft limits.
    QString line = QStringLiteral("G0");
    m_pendingAxes.clear();
    for (const QString& axis : axes) {
        const machine::MachineAxis* a = m->description().axis(axis);
        const QDoubleSpinBox* box = targetBox(axis);
        if (!a || !box)
            return;
        line += QStringLiteral(" %1%2").arg(
            axis, axisValue(box->value(), a->unit == machine::AxisUnit::Step));
        m_pendingAxes.append({axis, m_offsets->toMachine(axis, box->value())});
    }
    QString refusal;
    m_moveStarted = false;
    m_pending = m_context->mdi()->runOwnLine(line, &refusal);
    m_go->setEnabled(m_pending == 0);
    m_movingText = tr("Moving %1\u2026").arg(targetsText(true));
    // Nothing moves before the check has passed (MachineMdi::started).
    m_result->setText(!m_pending ? tr("Go-to refused: %1").arg(refusal)
                                 : tr("Checking the go-to of %1\u2026").arg(targetsText(false)));
}

void MachineGoTo::onEnded(quint64 id, bool ok, const QString& message)
{
    if (id == 0 || id != m_pending)
        return;
    m_pending = 0;
    m_go->setEnabled(true);
    if (!ok) {
        // The check's refusal (nothing sent) or the run's end short of the targets.
        m_result->setText(m_moveStarted ? tr("Go-to failed: %1").arg(message)
                                        : tr("Go-to refused: %1").arg(message));
        return;
    }
    readPositions();
}

// The run's move ended with the axes standing. "Arrived" only where a status read asked for
// after that counts an axis at its target: a STOP ends a move short of it, and a board that
// reports no position (the E-LAB) corrects its count only after the stop (RequestRelPosition),
// ahead of that read. One read per controller the go-to moved.
void MachineGoTo::readPositions()
{
    const machine::Machine* m = m_context->machine();
    if (!m)
        return;
    QList<ControllerSession*> sessions;
    for (const Pending& p : std::as_const(m_pendingAxes)) {
        const machine::MachineAxis* a = m->description().axis(p.axis);
        ControllerSession* session = a ? m->session(a->controller) : nullptr;
        if (session && !sessions.contains(session))
            sessions << session;
    }
    if (sessions.isEmpty())
        return;
    const QString names = axisNames();
    m_result->setText(m_pendingAxes.size() == 1
                          ? tr("%1 stands: reading its position\u2026").arg(names)
                          : tr("%1 stand: reading their positions\u2026").arg(names));
    for (const QMetaObject::Connection& c : std::as_const(m_confirm))
        disconnect(c);
    m_confirm.clear();
    m_reads.clear();
    m_readFailed = false;
    for (ControllerSession* session : std::as_const(sessions)) {
        const RequestId read = session->refreshStatus();
        m_reads << read;
        m_confirm << connect(session, &ControllerSession::requestFinished, this,
                             [this, read](const CommandResult& r) {
                                 if (r.id != read || !m_reads.removeOne(read))
                                     return;
                                 m_readFailed = m_readFailed || !r.ok();
                                 if (m_reads.isEmpty())
                                     judgeArrival();
                             });
    }
}

void MachineGoTo::judgeArrival()
{
    for (const QMetaObject::Connection& c : std::as_const(m_confirm))
        disconnect(c);
    m_confirm.clear();
    const machine::Machine* m = m_context->machine();
    if (!m)
        return;
    if (m_readFailed) {
        m_result->setText(
            m_pendingAxes.size() == 1
                ? tr("%1 stands; its position could not be read.").arg(axisNames())
                : tr("%1 stand; their positions could not be read.").arg(axisNames()));
        return;
    }
    QStringList arrived;
    QStringList short_;
    for (const Pending& p : std::as_const(m_pendingAxes)) {
        const machine::MachineAxis* a = m->description().axis(p.axis);
        if (!a)
            continue;
        const machine::MachineAxisStatus status = m->axisStatus(*a);
        if (status.known != machine::PositionKnowledge::Unknown &&
            qAbs(status.position - p.machineTarget) * a->stepsPerUnit < 0.5)
            arrived << a->name;
        else
            short_ << tr("%1 stopped at %2 before its target %3")
                          .arg(a->name, QString::number(status.position, 'f', 3),
                               QString::number(p.machineTarget, 'f', 3));
    }
    QStringList sentences;
    if (!arrived.isEmpty())
        sentences << tr("%1 arrived").arg(arrived.join(QStringLiteral(", ")));
    sentences += short_;
    m_result->setText(sentences.join(QStringLiteral("; ")) + QLatin1Char('.'));
}

QString MachineGoTo::axisNames() const
{
    QStringList names;
    for (const Pending& p : m_pendingAxes)
        names << p.axis;
    return names.join(QStringLiteral(", "));
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
