#pragma once
#include <QWidget>

class QCheckBox;
class QGridLayout;
class QLabel;
class QLineEdit;

namespace stepdeck::ui {

class AxisRowFilter;

// Above a list of many axes or drives (issue 32, step 5): a filter field (name or bus
// address), "Moving first", and how many rows show of how many. Its size never depends on
// what it shows, so typing or a count that changes moves nothing around it; in a narrow dock
// the filter field takes a row of its own.
class AxisListBar : public QWidget
{
    Q_OBJECT
public:
    AxisListBar(AxisRowFilter* filter, QWidget* parent = nullptr);

    QLineEdit* filterEdit() const { return m_edit; }
    QCheckBox* movingFirstBox() const { return m_movingFirst; }
    QString countText() const;

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void updateCount();
    void arrange(bool twoRows); // the filter field and the rest in one row or two

    AxisRowFilter* m_filter;
    QLineEdit* m_edit;
    QCheckBox* m_movingFirst;
    QLabel* m_count;
    QGridLayout* m_grid = nullptr;
    bool m_twoRows = false;
};

} // namespace stepdeck::ui
