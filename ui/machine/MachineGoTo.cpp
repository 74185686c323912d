#include "MachineGoTo.h"
#include "common/ElidedLabel.h"
#include "machine/Machine.h"
#include "machine/MachineContext.h"
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace stepdeck::ui {

MachineGoTo::MachineGoTo(MachineContext* context, QWidget* parent)
    : QWidget(parent), m_context(context), m_axis(new QComboBox(this)),
      m_target(new QDoubleSpinBox(this)), m_go(new QPushButton(tr("Go to"), this)),
      m_result(new ElidedLabel(this))
{
    setObjectName(QStringLiteral("machineGoTo"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* row = new QHBoxLayout;
    row->addWidget(new QLabel(tr("Go to:"), this));
    row->addWidget(m_axis);
    row->addWidget(m_target, 1);
    row->addWidget(m_go);
    layout->addLayout(row);
    layout->addWidget(m_result);
    m_target->setRange(-1e6, 1e6);
    m_target->setToolTip(tr("Absolute target in the axis' unit; the axis must be referenced"));
    m_go->setFocusPolicy(Qt::NoFocus);
    connect(m_go, &QPushButton::clicked, this, &MachineGoTo::go);
    connect(m_axis, &QComboBox::currentIndexChanged, this, &MachineGoTo::updateUnit);
    connect(context, &MachineContext::machineChanged, this, &MachineGoTo::rebuild);
    rebuild();
}

void MachineGoTo::rebuild()
{
    m_axis->clear();
    m_pending = 0;
    m_result->clear();
    machine::Machine* m = m_context->machine();
    if (!m)
        return;
    for (const machine::MachineAxis& a : m->description().axes)
        m_axis->addItem(a.name, a.name);
    connect(m, &machine::Machine::moveFinished, this, &MachineGoTo::onFinished,
            Qt::UniqueConnection);
    updateUnit();
}

void MachineGoTo::updateUnit()
{
    const machine::Machine* m = m_context->machine();
    const machine::MachineAxis* a =
        m ? m->description().axis(m_axis->currentData().toString()) : nullptr;
    if (!a)
        return;
    const bool steps = a->unit == machine::AxisUnit::Step;
    m_target->setDecimals(steps ? 0 : 3);
    m_target->setSuffix(QLatin1Char(' ') + machine::unitKey(a->unit));
}

void MachineGoTo::go()
{
    machine::Machine* m = m_context->machine();
    if (!m || m_axis->currentIndex() < 0)
        return;
    const QString axis = m_axis->currentData().toString();
    QString refusal;
    // Refused as a whole before anything is sent: unknown or unreferenced axis, a controller
    // not connected, a target outside the soft limits (Machine::move).
    m_pending = m->move({{axis, m_target->value()}}, true, &refusal);
    m_result->setText(m_pending ? tr("Moving %1 to %2\u2026").arg(axis, m_target->text())
                                : tr("Go-to refused: %1").arg(refusal));
}

void MachineGoTo::onFinished(quint64 id, bool ok, const QString& message)
{
    if (id == 0 || id != m_pending)
        return;
    m_pending = 0;
    m_result->setText(ok ? tr("%1 arrived.").arg(m_axis->currentData().toString())
                         : tr("Go-to failed: %1").arg(message));
}

QString MachineGoTo::resultText() const
{
    return m_result->text();
}

} // namespace stepdeck::ui
