#pragma once
#include <QLabel>
#include <QStringList>

namespace stepdeck::ui {

// Fixes a one-line label's size to that of the widest of the texts it can show. A text that
// changes often (a rate, a counter) then never re-lays out the widgets around it: QLabel::
// setText calls updateGeometry() for every new text, and that invalidates every layout up to
// the window unless the label's minimum and maximum sizes are equal (issue 21: the toolbar's
// poll rate re-laid out the main window and its docks twice a second). The label's own size
// hint measures each text, so margins, frame and indent count as they would. Called again
// with other texts, it sizes the label for those.
inline void reserveTextSize(QLabel* label, const QStringList& texts)
{
    label->ensurePolished();
    label->setMinimumSize(0, 0); // measured afresh: the room may shrink as well as grow
    label->setMaximumSize(QWIDGETSIZE_MAX, QWIDGETSIZE_MAX);
    const QString shown = label->text();
    QSize size;
    for (const QString& text : texts) {
        label->setText(text);
        size = size.expandedTo(label->sizeHint());
    }
    label->setText(shown);
    label->setFixedSize(size);
}

} // namespace stepdeck::ui
