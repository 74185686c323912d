#pragma once
// Shared by the machine editor tests: the shipped examples and typing into the editor's cells
// as an operator does (the edit signals fire as they do for a person).
#include "machine/AxesTable.h"
#include "machine/ControllersTable.h"
#include "machine/MachineEditor.h"
#include <QComboBox>
#include <QDir>
#include <QLineEdit>
#include <QtTest>
#include <memory>

namespace stepdeck::test {

inline QString exampleDir()
{
    return QStringLiteral(STEPDECK_SOURCE_DIR "/docs/examples");
}

inline QString example(const QString& name)
{
    return exampleDir() + QLatin1Char('/') + name;
}

inline QStringList exampleFiles()
{
    return QDir(exampleDir()).entryList({QStringLiteral("*.machine.json")}, QDir::Files);
}

// Opens a shipped example in a new editor.
inline std::unique_ptr<ui::MachineEditor> editorWith(const QString& exampleName)
{
    auto editor = std::make_unique<ui::MachineEditor>();
    if (!editor->openFile(example(exampleName)))
        qWarning("%s", qPrintable(editor->messageText()));
    return editor;
}

// Replaces a line edit's text by typing (textEdited fires, as for a person).
inline void typeInto(QWidget* cell, const QString& text)
{
    auto* edit = qobject_cast<QLineEdit*>(cell);
    QVERIFY2(edit, "not a text cell");
    edit->selectAll();
    QTest::keyClick(edit, Qt::Key_Backspace);
    if (!text.isEmpty())
        QTest::keyClicks(edit, text);
}

// Chooses the item with text in a combo cell.
inline void choose(QWidget* cell, const QString& text)
{
    auto* combo = qobject_cast<QComboBox*>(cell);
    QVERIFY2(combo, "not a choice cell");
    const int index = combo->findText(text);
    QVERIFY2(index >= 0, qPrintable(text));
    combo->setCurrentIndex(index);
}

// The cell of a table ("controllers", "axes"), the name field ("name") or the spindle scale
// ("spindle").
inline QWidget* editorCell(ui::MachineEditor* editor, const QString& table, int row,
                           const QString& key)
{
    if (table == QLatin1String("name"))
        return editor->nameEdit();
    if (table == QLatin1String("spindle"))
        return editor->maxRpmEdit();
    if (table == QLatin1String("controllers"))
        return editor->controllersTable()->cell(row, key);
    return editor->axesTable()->cell(row, key);
}

} // namespace stepdeck::test
