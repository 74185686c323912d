#pragma once
#include <QLayout>

namespace stepdeck::ui {

// Empties a layout that a page rebuilds (a new model, a machine opened): every item goes, with
// its widget, and nested layouts are emptied the same way.
inline void deleteLayoutItems(QLayout* layout)
{
    while (QLayoutItem* item = layout->takeAt(0)) {
        if (QLayout* inner = item->layout())
            deleteLayoutItems(inner);
        delete item->widget();
        delete item;
    }
}

} // namespace stepdeck::ui
