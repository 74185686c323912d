#pragma once
#include "program/ProgramBlock.h"
#include <QMap>
#include <QPlainTextEdit>

namespace stepdeck::ui {

// The program's text (issue 20): line numbers in a gutter, the check's errors marked at their
// lines (a red mark in the gutter, the line tinted; the message in the tooltip of both), and
// the running line highlighted. Read-only while a program runs: what runs is what is shown.
class ProgramEditor : public QPlainTextEdit
{
    Q_OBJECT
public:
    explicit ProgramEditor(QWidget* parent = nullptr);

    // The check's errors; an empty list clears the marks. Messages of one line are joined.
    void setErrors(const QList<program::ProgramError>& errors);
    QList<int> errorLines() const { return m_errors.keys(); }
    QString errorAt(int line) const { return m_errors.value(line); }
    // The cursor to a line (1-based) and column (1-based; 0: unknown), the word there selected
    // (the whole line without a column), shown, and the focus to the text: where an error is.
    // False when the line is not in the text (past the excerpt of a large file).
    bool goToLine(int line, int column = 0);
    // The block running (1-based line; 0: none). The view follows it while it runs.
    void setRunningLine(int line);
    int runningLine() const { return m_runningLine; }
    // While running the text cannot be changed (the highlight stays where the runner is).
    void setRunning(bool running);
    bool isRunning() const { return m_running; }
    // The text is an excerpt of a file too long to edit here (ProgramFiles): never editable.
    void setExcerpt(bool excerpt);
    bool isExcerpt() const { return m_excerpt; }

    int gutterWidth() const;
    // The line (1-based) at a point of the viewport, 0 below the last line.
    int lineAt(const QPoint& viewportPoint) const;
    // The tooltip shown over a line: its error, if any.
    QString toolTipForLine(int line) const { return errorAt(line); }

protected:
    bool event(QEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    friend class ProgramEditorGutter;
    void paintGutter(QPaintEvent* event);
    void updateGutterWidth();
    void updateGutter(const QRect& rect, int dy);
    void updateSelections();
    QTextEdit::ExtraSelection lineSelection(int line, const QColor& color) const;

    QWidget* m_gutter;
    QMap<int, QString> m_errors; // line -> message(s)
    int m_runningLine = 0;
    bool m_running = false;
    bool m_excerpt = false;
};

} // namespace stepdeck::ui
