#include "SoftLimitsDialog.h"
#include "common/ElidedLabel.h"
#include "machine/MachineContext.h"
#include <QCheckBox>
#include <QDialogButtonBox>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QToolButton>
#include <limits>

namespace stepdeck::ui {

namespace {
int toSpin(qint64 steps)
{
    return int(qBound(qint64(std::numeric_limits<int>::min()), steps,
                      qint64(std::numeric_limits<int>::max())));
}
} // namespace

SoftLimitsDialog::SoftLimitsDialog(MachineContext* context, QWidget* parent)
    : QDialog(parent), m_context(context), m_problem(new ElidedLabel(this, 2))
{
    setObjectName(QStringLiteral("softLimitsDialog"));
    setWindowTitle(tr("Soft limits"));
    auto* intro = new QLabel(tr("Jog and moves stop or are refused at these positions (machine "
                                "steps) once the axis is referenced. Minimum equal to maximum: "
                                "no limit set."),
                             this);
    intro->setWordWrap(true);
    auto* grid = new QGridLayout;
    grid->addWidget(new QLabel(tr("Axis")), 0, 0);
    grid->addWidget(new QLabel(tr("On")), 0, 1);
    grid->addWidget(new QLabel(tr("Minimum")), 0, 2);
    grid->addWidget(new QLabel(tr("Maximum")), 0, 4);
    int r = 1;
    for (Axis axis : context->axes()) {
        const AxisSoftLimit l = context->softLimits().limit(axis);
        Row row;
        row.enabled = new QCheckBox(this);
        row.enabled->setChecked(l.enabled);
        row.minimum = new QSpinBox(this);
        row.maximum = new QSpinBox(this);
        for (QSpinBox* box : {row.minimum, row.maximum}) {
            box->setRange(std::numeric_limits<int>::min(), std::numeric_limits<int>::max());
            box->setSuffix(tr(" steps"));
        }
        row.minimum->setValue(toSpin(l.minimum));
        row.maximum->setValue(toSpin(l.maximum));
        const AxisStatus a = context->status().axes.value(axis);
        auto here = [&](QSpinBox* box) {
            auto* b = new QToolButton(this);
            b->setText(tr("here"));
            b->setToolTip(tr("The current position of %1").arg(axisName(axis)));
            b->setEnabled(context->isConnected() && a.referenced);
            connect(b, &QToolButton::clicked, this, [this, axis, box] {
                box->setValue(toSpin(m_context->status().axes.value(axis).position));
            });
            return b;
        };
        grid->addWidget(new QLabel(axisName(axis), this), r, 0);
        grid->addWidget(row.enabled, r, 1);
        grid->addWidget(row.minimum, r, 2);
        grid->addWidget(here(row.minimum), r, 3);
        grid->addWidget(row.maximum, r, 4);
        grid->addWidget(here(row.maximum), r, 5);
        m_rows.insert(axis, row);
        ++r;
    }
    m_problem->setStyleSheet(QStringLiteral("QLabel { color: #c62828; }"));
    // Two lines reserved (the full text in the tooltip): OK and Cancel never move.
    m_problem->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addLayout(grid);
    layout->addWidget(m_problem);
    layout->addWidget(buttons);
}

void SoftLimitsDialog::accept()
{
    for (auto it = m_rows.cbegin(); it != m_rows.cend(); ++it) {
        if (it->minimum->value() > it->maximum->value()) {
            m_problem->setText(
                tr("Axis %1: the minimum lies above the maximum.").arg(axisName(it.key())));
            return;
        }
    }
    for (auto it = m_rows.cbegin(); it != m_rows.cend(); ++it) {
        AxisSoftLimit l;
        l.enabled = it->enabled->isChecked();
        l.minimum = it->minimum->value();
        l.maximum = it->maximum->value();
        l.rangeSet = l.maximum > l.minimum;
        m_context->setSoftLimit(it.key(), l);
    }
    QDialog::accept();
}

} // namespace stepdeck::ui
