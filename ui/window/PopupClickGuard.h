#pragma once
#include <QObject>

namespace stepdeck::ui {

// A click that closes a popup (a menu, a combo box's list, a completer) does nothing else
// (issue 31, a safety finding: a mis-click beside an open menu fired PANIC). On platforms
// whose Qt replays the press that closes a popup to the widget under the pointer
// (QPlatformIntegration::ReplayMousePressOutsidePopup), that replay is what would reach the
// window: installed on the application by the main window, this marks every popup widget
// Qt::WA_NoMouseReplay when it is polished or shown, whoever made it (the menu bar's menus,
// context menus made on the fly). STOP alone still acts through a popup (SafetyKeyFilter).
class PopupClickGuard : public QObject
{
    Q_OBJECT
public:
    explicit PopupClickGuard(QObject* parent = nullptr) : QObject(parent) {}

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
};

} // namespace stepdeck::ui
