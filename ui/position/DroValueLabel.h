#pragma once
#include <QLabel>

namespace stepdeck::ui {

// The large digits of one DRO row with the unit in normal type at their right, in one box.
// Its size never depends on the value: the digits take the largest type, up to the DRO font,
// at which the reserved text (the longest value the axis shows, e.g. "≈-00000.000") fits the
// box, so they neither jump in size while the value changes nor get cut; a value longer still
// is drawn smaller rather than cut (issue 16: "≈" alone was left of a clipped value).
// text() is the value without the unit.
class DroValueLabel : public QLabel
{
    Q_OBJECT
public:
    explicit DroValueLabel(QWidget* parent = nullptr);

    void setDigitFont(const QFont& font);
    QFont digitFont() const { return m_digits; }
    void setUnit(const QString& unit);
    QString unit() const { return m_unit; }
    void setReservedText(const QString& text);
    // The digits' type as drawn now at this width (for tests).
    QFont shownDigitFont() const;
    bool textFits() const; // the value is drawn whole (it may be drawn smaller)

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;
    bool hasHeightForWidth() const override { return false; }
    int heightForWidth(int) const override { return -1; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    QRect textArea() const;
    QSize chrome() const;
    int unitWidth() const;
    // The largest digit type (at least kMinimumScale of the DRO font) in which text fits width.
    QFont fitted(const QString& text, int width) const;

    static constexpr double kMinimumScale = 0.5;
    QFont m_digits;
    QString m_unit;
    QString m_reserved = QStringLiteral("-0000.000");
};

} // namespace stepdeck::ui
