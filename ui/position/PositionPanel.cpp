#include "PositionPanel.h"
#include "common/Dialogs.h"
#include "main/MachineContext.h"
#include "position/UnitsDialog.h"
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QToolButton>

namespace stepdeck::ui {

PositionPanel::PositionPanel(MachineContext* context, QWidget* parent)
    : QWidget(parent), m_context(context), m_grid(new QGridLayout)
{
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(m_grid);
    auto* buttons = new QHBoxLayout;
    auto* units = new QToolButton(this);
    units->setText(tr("Units\u2026"));
    units->setToolTip(tr("Steps per mm or per degree for each axis"));
    auto* clear = new QToolButton(this);
    clear->setText(tr("Clear work offsets"));
    clear->setToolTip(tr("Show machine positions again (work origin = machine origin)"));
    for (QToolButton* b : {units, clear})
        b->setFocusPolicy(Qt::NoFocus);
    buttons->addWidget(units);
    buttons->addWidget(clear);
    buttons->addStretch(1);
    layout->addLayout(buttons);
    layout->addStretch(1);

    connect(units, &QToolButton::clicked, this, &PositionPanel::editUnits);
    connect(clear, &QToolButton::clicked, this, &PositionPanel::clearOffsets);
    connect(context, &MachineContext::modelChanged, this, &PositionPanel::rebuild);
    connect(context, &MachineContext::unitsChanged, this,
            [this] { onStatus(m_context->status()); });
    connect(context->session(), &ControllerSession::statusChanged, this, &PositionPanel::onStatus);
    rebuild();
}

void PositionPanel::rebuild()
{
    while (QLayoutItem* item = m_grid->takeAt(0)) {
        delete item->widget();
        delete item;
    }
    m_rows.clear();
    QFont big(QStringLiteral("monospace"));
    big.setStyleHint(QFont::Monospace);
    big.setPointSizeF(font().pointSizeF() * 2.6);
    big.setBold(true);
    QFont axisFont = font();
    axisFont.setPointSizeF(font().pointSizeF() * 2.2);
    axisFont.setBold(true);
    int r = 0;
    for (Axis axis : m_context->axes()) {
        Row row;
        auto* name = new QLabel(axisName(axis), this);
        name->setFont(axisFont);
        row.value = new QLabel(this);
        row.value->setFont(big);
        row.value->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        row.value->setMinimumWidth(
            QFontMetrics(big).horizontalAdvance(QStringLiteral("-0000.000")));
        row.value->setStyleSheet(QStringLiteral("QLabel { background: #101418; color: #7CFC9A; "
                                                "border-radius: 4px; padding: 2px 8px; }"));
        row.unit = new QLabel(this);
        row.steps = new QLabel(this);
        row.steps->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        row.state = new QLabel(this);
        row.state->setAlignment(Qt::AlignCenter);
        row.state->setMinimumWidth(84);
        auto* zero = new QToolButton(this);
        zero->setText(tr("Zero %1").arg(axisName(axis)));
        zero->setToolTip(
            tr("Set the work origin of %1 at the current position").arg(axisName(axis)));
        zero->setFocusPolicy(Qt::NoFocus);
        connect(zero, &QToolButton::clicked, this, [this, axis] { zeroAxis(axis); });
        m_grid->addWidget(name, 2 * r, 0, 2, 1);
        m_grid->addWidget(row.value, 2 * r, 1);
        m_grid->addWidget(row.unit, 2 * r, 2);
        m_grid->addWidget(row.state, 2 * r, 3);
        m_grid->addWidget(row.steps, 2 * r + 1, 1);
        m_grid->addWidget(zero, 2 * r + 1, 3);
        m_rows.insert(axis, row);
        ++r;
    }
    m_grid->setColumnStretch(1, 1);
    onStatus(m_context->status());
}

void PositionPanel::onStatus(const MachineStatus& status)
{
    for (auto it = m_rows.cbegin(); it != m_rows.cend(); ++it) {
        const Axis axis = it.key();
        const Row& row = it.value();
        const AxisStatus a = status.axes.value(axis);
        const AxisUnits u = m_context->units(axis);
        const double value = m_context->toUserUnits(axis, a.position);
        QString text =
            u.stepsPerUnit > 0 ? QString::number(value, 'f', 3) : QString::number(qint64(value));
        if (a.positionEstimated && a.positionKnown)
            text.prepend(QStringLiteral("\u2248"));
        row.value->setText(text);
        row.unit->setText(m_context->unitName(axis));
        row.steps->setText(tr("machine %1 steps").arg(a.position));
        QString state;
        QString style;
        if (!a.positionKnown) {
            state = tr("UNKNOWN");
            style = QStringLiteral("background:#ffcdd2; color:#8e0000;");
            row.value->setStyleSheet(QStringLiteral("QLabel { background: #101418; color: #6b7780;"
                                                    " border-radius: 4px; padding: 2px 8px; }"));
        } else {
            state = a.positionEstimated ? tr("ESTIMATED") : tr("REFERENCED");
            style = a.positionEstimated ? QStringLiteral("background:#ffe082; color:#4e3400;")
                                        : QStringLiteral("background:#c8e6c9; color:#1b5e20;");
            row.value->setStyleSheet(QStringLiteral("QLabel { background: #101418; color: #7CFC9A;"
                                                    " border-radius: 4px; padding: 2px 8px; }"));
        }
        row.state->setText(state);
        row.state->setStyleSheet(
            QStringLiteral("QLabel { %1 border-radius: 3px; font-weight: bold; padding: 2px; }")
                .arg(style));
        row.state->setToolTip(
            !a.positionKnown
                ? tr("Not referenced since the last panic, reset or reconnect: the position "
                     "is counted from where the axis was, not from the machine origin.")
            : a.positionEstimated
                ? tr("Integrated from commanded jog rates; the controller did not confirm it.")
                : tr("Referenced and confirmed."));
    }
}

QString PositionPanel::displayedValue(Axis axis) const
{
    return m_rows.contains(axis) ? m_rows.value(axis).value->text() : QString();
}

QString PositionPanel::stateText(Axis axis) const
{
    return m_rows.contains(axis) ? m_rows.value(axis).state->text() : QString();
}

void PositionPanel::zeroAxis(Axis axis)
{
    AxisUnits u = m_context->units(axis);
    u.workOffset = m_context->status().axes.value(axis).position;
    m_context->setUnits(axis, u);
}

void PositionPanel::clearOffsets()
{
    for (Axis axis : m_context->axes()) {
        AxisUnits u = m_context->units(axis);
        u.workOffset = 0;
        m_context->setUnits(axis, u);
    }
}

void PositionPanel::editUnits()
{
    dialogs::showForPart(new UnitsDialog(m_context, window()), this);
}

} // namespace stepdeck::ui
