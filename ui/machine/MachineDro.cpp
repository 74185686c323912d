#include "MachineDro.h"
#include "common/ElidedLabel.h"
#include "common/StyleSheet.h"
#include "machine/Machine.h"
#include "machine/MachineContext.h"
#include "position/DroValueLabel.h"
#include <QCoreApplication>
#include <QGridLayout>
#include <QLabel>

namespace stepdeck::ui {

namespace {
const QString kRed = QStringLiteral("background:#ffcdd2; color:#8e0000;");
const QString kAmber = QStringLiteral("background:#ffe082; color:#4e3400;");
const QString kGreen = QStringLiteral("background:#c8e6c9; color:#1b5e20;");
const QString kGrey = QStringLiteral("background:#eceff1; color:#37474f;");

QString unitWord(machine::AxisUnit unit)
{
    switch (unit) {
    case machine::AxisUnit::Millimetre:
        return QCoreApplication::translate("stepdeck::ui::MachineDro", "mm");
    case machine::AxisUnit::Degree:
        return QCoreApplication::translate("stepdeck::ui::MachineDro", "deg");
    case machine::AxisUnit::Step:
        break;
    }
    return QCoreApplication::translate("stepdeck::ui::MachineDro", "steps");
}

QString format(const machine::MachineAxis& axis, double value)
{
    return axis.unit == machine::AxisUnit::Step ? QString::number(qRound64(value))
                                                : QString::number(value, 'f', 3);
}
} // namespace

MachineDro::MachineDro(MachineContext* context, QWidget* parent)
    : QWidget(parent), m_context(context), m_grid(new QGridLayout(this))
{
    setObjectName(QStringLiteral("machineDro"));
    m_grid->setContentsMargins(0, 0, 0, 0);
    connect(context, &MachineContext::machineChanged, this, &MachineDro::rebuild);
    connect(context, &MachineContext::machineStatusChanged, this, &MachineDro::refresh);
    rebuild();
}

QStringList MachineDro::stateWords()
{
    return {tr("NO LINK"), tr("MOVING"), tr("UNKNOWN"), tr("ESTIMATED"), tr("REFERENCED")};
}

void MachineDro::rebuild()
{
    while (QLayoutItem* item = m_grid->takeAt(0)) {
        delete item->widget();
        delete item;
    }
    m_rows.clear();
    const machine::Machine* m = m_context->machine();
    if (!m)
        return;
    QFont big(QStringLiteral("monospace"));
    big.setStyleHint(QFont::Monospace);
    big.setPointSizeF(font().pointSizeF() * 2.2);
    big.setBold(true);
    QFont nameFont = font();
    nameFont.setPointSizeF(font().pointSizeF() * 2.0);
    nameFont.setBold(true);
    QFont badgeFont = font();
    badgeFont.setBold(true);
    int badgeWidth = 0;
    for (const QString& word : stateWords())
        badgeWidth = qMax(badgeWidth, QFontMetrics(badgeFont).horizontalAdvance(word) + 12);
    int r = 0;
    for (const machine::MachineAxis& axis : m->description().axes) {
        auto* name = new QLabel(axis.name, this);
        name->setFont(nameFont);
        Row row{new DroValueLabel(this), new QLabel(this), new ElidedLabel(this)};
        row.value->setObjectName(QStringLiteral("machineDroValue") + axis.name);
        row.value->setDigitFont(big);
        row.value->setUnit(unitWord(axis.unit));
        row.value->setReservedText(axis.unit == machine::AxisUnit::Step
                                       ? QStringLiteral("\u2248-0000000")
                                       : QStringLiteral("\u2248-00000.000"));
        row.state->setAlignment(Qt::AlignCenter);
        row.state->setFixedWidth(badgeWidth);
        row.detail->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
        row.detail->setStyleSheet(QStringLiteral("QLabel { color: palette(dark); }"));
        m_grid->addWidget(name, 2 * r, 0, 2, 1);
        m_grid->addWidget(row.value, 2 * r, 1);
        m_grid->addWidget(row.state, 2 * r, 2);
        m_grid->addWidget(row.detail, 2 * r + 1, 1, 1, 2);
        m_rows.insert(axis.name, row);
        ++r;
    }
    m_grid->setColumnStretch(1, 1);
    refresh();
}

void MachineDro::refresh()
{
    const machine::Machine* m = m_context->machine();
    if (!m)
        return;
    for (const machine::MachineAxis& axis : m->description().axes) {
        const ControllerSession* s = m->session(axis.controller);
        const bool linked = s && s->linkState() == LinkState::Connected;
        showAxis(m_rows.value(axis.name), m->axisStatus(axis), linked);
    }
}

void MachineDro::showAxis(const Row& row, const machine::MachineAxisStatus& a, bool linked)
{
    if (!row.value || !a.axis)
        return;
    const machine::MachineAxis& axis = *a.axis;
    QString text = format(axis, a.position);
    row.detail->setText(
        tr("%1 axis %2: %3 steps").arg(axis.controller, axisName(axis.axis)).arg(a.steps));
    if (!linked) {
        row.value->setText(text);
        setState(row, tr("NO LINK"), kGrey, true,
                 tr("Controller \"%1\" is not connected: this is the last value known, not the "
                    "position now.")
                     .arg(axis.controller));
        return;
    }
    if (a.known == machine::PositionKnowledge::Estimated)
        text.prepend(QStringLiteral("\u2248"));
    row.value->setText(text);
    if (a.known == machine::PositionKnowledge::Unknown)
        setState(row, tr("UNKNOWN"), kRed, true,
                 tr("Not referenced since the last panic, reset or reconnect: the position is "
                    "counted from where the axis was, not from the machine origin."));
    else if (a.moving)
        setState(row, tr("MOVING"), kAmber, false, tr("Moving, as the controller reports."));
    else if (a.known == machine::PositionKnowledge::Estimated)
        setState(row, tr("ESTIMATED"), kAmber, false,
                 tr("Estimated by the host; the controller did not confirm it."));
    else
        setState(row, tr("REFERENCED"), kGreen, false,
                 tr("Known from the controller: read back or set by a reference run."));
}

void MachineDro::setState(const Row& row, const QString& word, const QString& style, bool dim,
                          const QString& tip)
{
    row.state->setText(word);
    row.state->setToolTip(tip);
    setStyleSheetIfChanged(
        row.state,
        QStringLiteral("QLabel { %1 border-radius: 3px; font-weight: bold; padding: 2px; }")
            .arg(style));
    setStyleSheetIfChanged(row.value,
                           QStringLiteral("QLabel { background: #101418; color: %1;"
                                          " border-radius: 4px; padding: 2px 8px; }")
                               .arg(dim ? QStringLiteral("#6b7780") : QStringLiteral("#7CFC9A")));
}

QString MachineDro::displayedValue(const QString& axis) const
{
    return m_rows.contains(axis) ? m_rows.value(axis).value->text() : QString();
}

QString MachineDro::unitText(const QString& axis) const
{
    return m_rows.contains(axis) ? m_rows.value(axis).value->unit() : QString();
}

QString MachineDro::stateText(const QString& axis) const
{
    return m_rows.contains(axis) ? m_rows.value(axis).state->text() : QString();
}

QString MachineDro::detailText(const QString& axis) const
{
    return m_rows.contains(axis) ? m_rows.value(axis).detail->text() : QString();
}

} // namespace stepdeck::ui
