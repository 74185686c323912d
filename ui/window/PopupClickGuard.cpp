#include "PopupClickGuard.h"
#include <QEvent>
#include <QWidget>

namespace stepdeck::ui {

bool PopupClickGuard::eventFilter(QObject* watched, QEvent* event)
{
    const QEvent::Type type = event->type();
    if ((type == QEvent::Polish || type == QEvent::Show) && watched->isWidgetType()) {
        auto* widget = static_cast<QWidget*>(watched);
        if (widget->windowType() == Qt::Popup)
            widget->setAttribute(Qt::WA_NoMouseReplay);
    }
    return false; // the event goes on as usual
}

} // namespace stepdeck::ui
