#pragma once
// Layout checks of the GUI tests: texts an operator cannot read in full, and the geometry of
// the widgets an operator holds.
#include "common/ElidedLabel.h"
#include "common/LedIndicator.h"
#include "position/DroValueLabel.h"
#include <QAbstractButton>
#include <QAbstractScrollArea>
#include <QLabel>
#include <QStringList>

namespace stepdeck::test {

// The scroll area w is shown in (its widget or inside it), or nullptr.
inline QAbstractScrollArea* enclosingScrollArea(QWidget* w)
{
    for (QWidget* p = w; p; p = p->parentWidget()) {
        if (auto* area = qobject_cast<QAbstractScrollArea*>(p->parentWidget());
            area && area->viewport() == p)
            return area;
    }
    return nullptr;
}

// Why w's text cannot be read in full (narrower than its text, cut off on the right or left
// by the scroll area it sits in, elided), or an empty string. Vertical scrolling is allowed.
inline QString textProblem(QWidget* w)
{
    if (!w->isVisible())
        return {};
    QString text;
    int needed = 0;
    if (auto* dro = qobject_cast<ui::DroValueLabel*>(w)) {
        if (!dro->textFits())
            return QStringLiteral("\"%1\" does not fit its box").arg(dro->text());
        text = dro->text();
        needed = dro->minimumSizeHint().width();
    } else if (auto* elided = qobject_cast<ui::ElidedLabel*>(w)) {
        if (elided->isElided())
            return QStringLiteral("elided to \"%1\"")
                .arg(elided->shownLines().join(QLatin1Char(' ')));
        text = elided->text();
    } else if (auto* label = qobject_cast<QLabel*>(w)) {
        text = label->text();
        if (label->wordWrap()) {
            if (label->height() < label->heightForWidth(label->width()))
                return QStringLiteral("%1 px high, needs %2")
                    .arg(label->height())
                    .arg(label->heightForWidth(label->width()));
        } else {
            needed = label->sizeHint().width();
        }
    } else if (auto* button = qobject_cast<QAbstractButton*>(w)) {
        text = button->text();
        needed = button->sizeHint().width();
    } else if (auto* lamp = qobject_cast<ui::LedIndicator*>(w)) {
        text = lamp->text();
        needed = lamp->sizeHint().width();
    } else {
        return {};
    }
    if (text.isEmpty())
        return {};
    if (w->width() < needed)
        return QStringLiteral("\"%1\" %2 px wide, needs %3").arg(text).arg(w->width()).arg(needed);
    for (QWidget* p = w->parentWidget(); p; p = p->parentWidget()) {
        auto* area = qobject_cast<QAbstractScrollArea*>(p->parentWidget());
        if (!area || area->viewport() != p)
            continue;
        const int left = w->mapTo(p, QPoint(0, 0)).x();
        if (left < 0 || left + w->width() > p->width())
            return QStringLiteral("\"%1\" at x %2..%3 is cut off by a %4 px wide scroll area")
                .arg(text)
                .arg(left)
                .arg(left + w->width())
                .arg(p->width());
    }
    return {};
}

// Every text under root (root included) that cannot be read in full, "name: problem".
inline QStringList clippedTexts(QWidget* root)
{
    QStringList out;
    QList<QWidget*> widgets{root};
    widgets += root->findChildren<QWidget*>();
    for (QWidget* w : std::as_const(widgets)) {
        const QString problem = textProblem(w);
        if (!problem.isEmpty())
            out << QStringLiteral("%1 (%2): %3")
                       .arg(w->objectName(), QString::fromLatin1(w->metaObject()->className()),
                            problem);
    }
    return out;
}

// Where w is on the screen.
inline QRect globalRect(const QWidget* w)
{
    return QRect(w->mapToGlobal(QPoint(0, 0)), w->size());
}

} // namespace stepdeck::test
