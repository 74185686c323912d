#include "ProgramEditor.h"
#include <QFontDatabase>
#include <QHelpEvent>
#include <QPaintEvent>
#include <QPainter>
#include <QTextBlock>
#include <QToolTip>

namespace stepdeck::ui {

namespace {
const QColor kErrorLine(255, 220, 220);
const QColor kErrorMark(200, 0, 0);
const QColor kRunningLine(255, 236, 150);
} // namespace

// The line numbers and error marks left of the text.
class ProgramEditorGutter : public QWidget
{
public:
    explicit ProgramEditorGutter(ProgramEditor* editor) : QWidget(editor), m_editor(editor)
    {
        setObjectName(QStringLiteral("programGutter"));
        setMouseTracking(true);
    }
    QSize sizeHint() const override { return {m_editor->gutterWidth(), 0}; }

protected:
    void paintEvent(QPaintEvent* event) override { m_editor->paintGutter(event); }
    bool event(QEvent* event) override
    {
        if (event->type() == QEvent::ToolTip) {
            auto* help = static_cast<QHelpEvent*>(event);
            const int line = m_editor->lineAt(QPoint(0, help->pos().y()));
            const QString text = m_editor->toolTipForLine(line);
            if (text.isEmpty())
                QToolTip::hideText();
            else
                QToolTip::showText(help->globalPos(), text, this);
            return true;
        }
        return QWidget::event(event);
    }

private:
    ProgramEditor* m_editor;
};

ProgramEditor::ProgramEditor(QWidget* parent)
    : QPlainTextEdit(parent), m_gutter(new ProgramEditorGutter(this))
{
    setObjectName(QStringLiteral("programEditor"));
    setLineWrapMode(QPlainTextEdit::NoWrap);
    QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    setFont(mono);
    connect(this, &QPlainTextEdit::blockCountChanged, this, &ProgramEditor::updateGutterWidth);
    connect(this, &QPlainTextEdit::updateRequest, this, &ProgramEditor::updateGutter);
    updateGutterWidth();
}

int ProgramEditor::gutterWidth() const
{
    const int digits = QString::number(qMax(1, blockCount())).size();
    // Room for four digits at least, so short programs do not shift the text as they grow.
    return 8 + fontMetrics().horizontalAdvance(QLatin1Char('9')) * qMax(4, digits) +
           fontMetrics().height() / 2 + 4;
}

void ProgramEditor::updateGutterWidth()
{
    setViewportMargins(gutterWidth(), 0, 0, 0);
}

void ProgramEditor::updateGutter(const QRect& rect, int dy)
{
    if (dy != 0)
        m_gutter->scroll(0, dy);
    else
        m_gutter->update(0, rect.y(), m_gutter->width(), rect.height());
}

void ProgramEditor::resizeEvent(QResizeEvent* event)
{
    QPlainTextEdit::resizeEvent(event);
    const QRect r = contentsRect();
    m_gutter->setGeometry(QRect(r.left(), r.top(), gutterWidth(), r.height()));
}

void ProgramEditor::paintGutter(QPaintEvent* event)
{
    QPainter painter(m_gutter);
    painter.fillRect(event->rect(), palette().color(QPalette::Window));
    QTextBlock block = firstVisibleBlock();
    int top = qRound(blockBoundingGeometry(block).translated(contentOffset()).top());
    int bottom = top + qRound(blockBoundingRect(block).height());
    const int markSize = fontMetrics().height() / 2;
    while (block.isValid() && top <= event->rect().bottom()) {
        const int line = block.blockNumber() + 1;
        if (block.isVisible() && bottom >= event->rect().top()) {
            if (line == m_runningLine)
                painter.fillRect(0, top, m_gutter->width(), bottom - top, kRunningLine);
            if (m_errors.contains(line)) {
                painter.setPen(Qt::NoPen);
                painter.setBrush(kErrorMark);
                painter.drawEllipse(3, top + (bottom - top - markSize) / 2, markSize, markSize);
            }
            painter.setPen(m_errors.contains(line) ? kErrorMark
                                                   : palette().color(QPalette::PlaceholderText));
            painter.drawText(0, top, m_gutter->width() - 4, fontMetrics().height(), Qt::AlignRight,
                             QString::number(line));
        }
        block = block.next();
        top = bottom;
        bottom = top + qRound(blockBoundingRect(block).height());
    }
}

int ProgramEditor::lineAt(const QPoint& viewportPoint) const
{
    const QTextBlock block = cursorForPosition(viewportPoint).block();
    if (!block.isValid())
        return 0;
    const QRectF geometry = blockBoundingGeometry(block).translated(contentOffset());
    if (viewportPoint.y() > geometry.bottom())
        return 0;
    return block.blockNumber() + 1;
}

bool ProgramEditor::event(QEvent* event)
{
    // An error's message over its line of text too, not only over the gutter's mark.
    if (event->type() == QEvent::ToolTip) {
        auto* help = static_cast<QHelpEvent*>(event);
        const QPoint inViewport = viewport()->mapFrom(this, help->pos());
        const QString text = toolTipForLine(lineAt(inViewport));
        if (text.isEmpty())
            QToolTip::hideText();
        else
            QToolTip::showText(help->globalPos(), text, this);
        return true;
    }
    return QPlainTextEdit::event(event);
}

void ProgramEditor::setErrors(const QList<program::ProgramError>& errors)
{
    m_errors.clear();
    for (const program::ProgramError& e : errors) {
        QString& text = m_errors[e.line];
        if (!text.isEmpty())
            text += QLatin1Char('\n');
        text += e.text();
    }
    updateSelections();
    m_gutter->update();
}

void ProgramEditor::setRunningLine(int line)
{
    if (line == m_runningLine)
        return;
    m_runningLine = line;
    updateSelections();
    m_gutter->update();
    if (line > 0 && m_running) {
        // Follow the runner; the text cannot be edited now, so nothing moves under a cursor.
        const QTextBlock block = document()->findBlockByNumber(line - 1);
        if (block.isValid()) {
            QTextCursor cursor(block);
            setTextCursor(cursor);
            ensureCursorVisible();
        }
    }
}

bool ProgramEditor::goToLine(int line, int column)
{
    const QTextBlock block = document()->findBlockByNumber(line - 1);
    if (line < 1 || !block.isValid())
        return false;
    const QString text = block.text();
    int from = column >= 1 ? qMin(column - 1, int(text.size())) : 0;
    int to = from;
    while (to < text.size() && !text.at(to).isSpace())
        ++to;
    if (column < 1 || to == from) { // no word there: the whole line
        from = 0;
        to = int(text.size());
    }
    // Anchored at the word's end, the cursor at its start: the caret stands at the column.
    QTextCursor cursor(block);
    cursor.setPosition(block.position() + to);
    cursor.setPosition(block.position() + from, QTextCursor::KeepAnchor);
    setTextCursor(cursor);
    ensureCursorVisible();
    window()->activateWindow();
    setFocus(Qt::OtherFocusReason);
    return true;
}

void ProgramEditor::setExcerpt(bool excerpt)
{
    m_excerpt = excerpt;
    setReadOnly(m_running || excerpt);
}

void ProgramEditor::setRunning(bool running)
{
    m_running = running;
    setReadOnly(running || m_excerpt);
    if (!running)
        setRunningLine(0);
}

QTextEdit::ExtraSelection ProgramEditor::lineSelection(int line, const QColor& color) const
{
    QTextEdit::ExtraSelection selection;
    selection.format.setBackground(color);
    selection.format.setProperty(QTextFormat::FullWidthSelection, true);
    selection.cursor = QTextCursor(document()->findBlockByNumber(line - 1));
    selection.cursor.clearSelection();
    return selection;
}

void ProgramEditor::updateSelections()
{
    QList<QTextEdit::ExtraSelection> selections;
    for (auto it = m_errors.cbegin(); it != m_errors.cend(); ++it) {
        if (it.key() >= 1 && it.key() <= blockCount())
            selections << lineSelection(it.key(), kErrorLine);
    }
    if (m_runningLine >= 1 && m_runningLine <= blockCount())
        selections << lineSelection(m_runningLine, kRunningLine);
    setExtraSelections(selections);
}

} // namespace stepdeck::ui
