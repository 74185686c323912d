#pragma once
#include <QLabel>

namespace stepdeck::ui {

// A label whose size never depends on its text, so a new message never re-flows the widgets
// around it (docs/architecture.md, "Main window layout"). It reserves room for a fixed number
// of lines, wraps the text inside them and elides what does not fit ("…"); the tooltip then
// shows the full text. With reserved texts it instead reserves, at its current width, the
// height of the longest of them (height-for-width): a banner whose possible texts are known
// shows each of them in full and keeps its height when the text changes.
// text() is the full text; plain text only.
class ElidedLabel : public QLabel
{
    Q_OBJECT
public:
    explicit ElidedLabel(QWidget* parent = nullptr, int lines = 1);

    void setLines(int lines);
    int lines() const { return m_lines; }
    // Texts whose height is reserved (e.g. every text a banner can show); empty: lines() only.
    void setReservedTexts(const QStringList& texts);
    // The narrowest width the label asks of its layout (its text never widens it).
    void setMinimumTextWidth(int pixels);

    // The lines as drawn at the current width, the last one elided if the text is longer.
    QStringList shownLines() const;
    bool isElided() const;
    // What the tooltip shows now: the full text when it is elided, then toolTip().
    QString toolTipText() const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;
    bool hasHeightForWidth() const override;
    int heightForWidth(int width) const override;

protected:
    bool event(QEvent* event) override;
    void paintEvent(QPaintEvent* event) override;

private:
    // Margins around the text: frame, style-sheet padding and QLabel::margin().
    QMargins textMargins() const;
    int textHeight(int lineCount) const;
    int lineCount(const QString& text, int textWidth) const;
    // The text broken into at most maxLines lines of textWidth; elided marks a cut.
    QStringList layoutLines(int textWidth, int maxLines, bool* elided) const;
    QStringList currentLines(bool* elided) const;

    int m_lines = 1;
    int m_minimumTextWidth = 0;
    QStringList m_reserved;
};

} // namespace stepdeck::ui
