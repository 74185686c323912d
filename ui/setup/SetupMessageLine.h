#pragma once
#include <QLabel>

namespace stepdeck::ui {

// The setup page's message: always one line high, whatever it says (a message never re-flows
// the form next to it). A text too long for the width is elided ("…"); the tooltip holds the
// whole of it, with detail lines (every invalid value, one per line), so nothing is cut off
// for good (issue 16).
class SetupMessageLine : public QLabel
{
    Q_OBJECT
public:
    explicit SetupMessageLine(QWidget* parent = nullptr);

    // text: one line (newlines become "; "); details: shown one per line in the tooltip.
    void setMessage(const QString& text, const QStringList& details = {});
    QString fullText() const { return m_full; }
    QStringList details() const { return m_details; }

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void elide();

    QString m_full;
    QStringList m_details;
};

} // namespace stepdeck::ui
