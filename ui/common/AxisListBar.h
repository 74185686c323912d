#pragma once
#include <QWidget>

class QCheckBox;
class QLabel;
class QLineEdit;

namespace stepdeck::ui {

class AxisRowFilter;

// Above a list of many axes or drives (issue 32, step 5): a filter field (name or bus
// address), "Moving first", and how many rows show of how many. Its size never depends on
// what it shows, so typing or a count that changes moves nothing around it.
class AxisListBar : public QWidget
{
    Q_OBJECT
public:
    AxisListBar(AxisRowFilter* filter, QWidget* parent = nullptr);

    QLineEdit* filterEdit() const { return m_edit; }
    QCheckBox* movingFirstBox() const { return m_movingFirst; }
    QString countText() const;

private:
    void updateCount();

    AxisRowFilter* m_filter;
    QLineEdit* m_edit;
    QCheckBox* m_movingFirst;
    QLabel* m_count;
};

} // namespace stepdeck::ui
