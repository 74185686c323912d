#pragma once
#include "model/ModelPresentation.h"
#include <QGroupBox>

class QGridLayout;
class QLabel;

namespace stepdeck::ui {

class LedIndicator;

// One raw status word of the model: its value in hex and one lamp per documented bit, named
// as in the manual, with plain words in the tooltip.
class RawWordView : public QGroupBox
{
    Q_OBJECT
public:
    explicit RawWordView(const StatusWordInfo& info, QWidget* parent = nullptr);

    void setValue(const QVariant& value); // invalid: unknown (not read yet)
    QString hexText() const;
    LedIndicator* lamp(const QString& bitName) const;
    const StatusWordInfo& info() const { return m_info; }
    // The same kind of word of another drive (issue 32: one view follows the drive chosen in a
    // list of many): its key in MachineStatus::raw and the title to show. The value is unknown
    // until setValue().
    void retarget(const QString& key, const QString& title);
    QString fullTitle() const { return m_title; }
    // Two lamp columns if they fit into room pixels (the width the view may take), else one.
    void fitWidth(int room);
    int columns() const { return m_columns; }

    // The title does not count: it is elided to the width (full in the tooltip).
    QSize minimumSizeHint() const override;

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void setColumns(int columns);

    void showTitle();

    StatusWordInfo m_info;
    QString m_title; // the whole title; the frame shows it elided to its width
    QLabel* m_key;
    QLabel* m_hex;
    QGridLayout* m_grid = nullptr;
    int m_columns = 0;
    QList<QPair<StatusBitInfo, LedIndicator*>> m_lamps;
};

} // namespace stepdeck::ui
