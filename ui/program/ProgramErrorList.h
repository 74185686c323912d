#pragma once
#include "program/ProgramBlock.h"
#include <QWidget>

class QListWidget;
class QListWidgetItem;

namespace stepdeck::ui {

class ElidedLabel;
class ProgramEditor;

// The check's errors of the Program page, all of them (issue 31 finding: the check line named
// only the first): "line N: message" per entry, the preview's last tab (issue 47 item 12: beside
// the path a program with errors still has; a program that does not parse has no path, and the
// list is then the one tab shown: nothing moves, nothing grows).
// Clicking an entry (or Enter on it) puts the editor's cursor at the error's line and column,
// selects the word there and gives the editor the focus. It follows each check (setErrors):
// errors fixed leave the list.
class ProgramErrorList : public QWidget
{
    Q_OBJECT
public:
    ProgramErrorList(ProgramEditor* editor, QWidget* parent);

    void setErrors(const QList<program::ProgramError>& errors);
    int errorCount() const;
    QListWidget* list() const { return m_list; }
    QString headerText() const;

private:
    void goTo(const QListWidgetItem* item);

    ProgramEditor* m_editor;
    ElidedLabel* m_header;
    QListWidget* m_list;
};

} // namespace stepdeck::ui
