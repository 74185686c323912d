#pragma once
#include <QWidget>

namespace stepdeck::ui {

// QWidget::setStyleSheet re-parses the sheet and re-polishes the widget (and relayouts its
// parent) even when the sheet is the same. Panels that restyle on every status poll use this,
// so an unchanged state costs nothing (issue 10, idle cost).
inline void setStyleSheetIfChanged(QWidget* widget, const QString& sheet)
{
    if (widget->styleSheet() != sheet)
        widget->setStyleSheet(sheet);
}

} // namespace stepdeck::ui
