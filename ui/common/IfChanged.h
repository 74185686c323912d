#pragma once
#include <QWidget>

namespace stepdeck::ui {

// Setters for panels that refresh on every status poll (20/s). Qt does the work even when the
// value is the same, so an unchanged state would still cost that work every poll (issues 10
// and 21, idle cost); these compare with what the widget shows now and skip only then, so no
// change is ever lost.

// QWidget::setStyleSheet re-parses the sheet and re-polishes the widget (and relayouts its
// parent) even when the sheet is the same.
inline void setStyleSheetIfChanged(QWidget* widget, const QString& sheet)
{
    if (widget->styleSheet() != sheet)
        widget->setStyleSheet(sheet);
}

// QWidget::setToolTip sends a ToolTipChange event through the application's event filters
// (and the accessibility bridge) even when the tip is the same.
inline void setToolTipIfChanged(QWidget* widget, const QString& tip)
{
    if (widget->toolTip() != tip)
        widget->setToolTip(tip);
}

} // namespace stepdeck::ui
