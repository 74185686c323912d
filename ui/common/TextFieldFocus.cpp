#include "TextFieldFocus.h"
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QTextEdit>

namespace stepdeck::ui {

bool textFieldHasFocus()
{
    QWidget* focus = QApplication::focusWidget();
    if (qobject_cast<QLineEdit*>(focus) || qobject_cast<QAbstractSpinBox*>(focus) ||
        qobject_cast<QPlainTextEdit*>(focus) || qobject_cast<QTextEdit*>(focus))
        return true;
    auto* combo = qobject_cast<QComboBox*>(focus);
    return combo && combo->isEditable();
}

} // namespace stepdeck::ui
