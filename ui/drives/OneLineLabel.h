#pragma once
#include <QLabel>
#include <QResizeEvent>

namespace stepdeck::ui::drives {

// One line of text that never grows or re-flows its neighbours: elided to the width it gets,
// the whole text in the tooltip (and in fullText() for tests).
class OneLineLabel : public QLabel
{
public:
    explicit OneLineLabel(QWidget* parent) : QLabel(parent)
    {
        setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
        setTextInteractionFlags(Qt::TextSelectableByMouse);
    }
    void setFullText(const QString& text)
    {
        m_full = text;
        setToolTip(text);
        refit();
    }
    const QString& fullText() const { return m_full; }
    QSize sizeHint() const override { return {60, QLabel::sizeHint().height()}; }
    QSize minimumSizeHint() const override { return {0, QLabel::minimumSizeHint().height()}; }

protected:
    void resizeEvent(QResizeEvent* event) override
    {
        QLabel::resizeEvent(event);
        refit();
    }

private:
    void refit() { setText(fontMetrics().elidedText(m_full, Qt::ElideRight, qMax(0, width()))); }
    QString m_full;
};

// The panels keep QLabel pointers; every one of them was made as a OneLineLabel.
inline OneLineLabel* elided(QLabel* label)
{
    return static_cast<OneLineLabel*>(label);
}

} // namespace stepdeck::ui::drives
