#pragma once
#include <QSortFilterProxyModel>

namespace stepdeck::ui {

// The rows of a list of axes or drives that stays usable with a full bus of 254 drives
// (issue 32, step 5): the rows whose text contains what the operator typed, the moving ones
// first when asked, otherwise in the controller's order. The source model gives each row the
// text it is found by (FilterTextRole: its names and its bus address) and whether it moves
// (MovingRole) in column 0.
class AxisRowFilter : public QSortFilterProxyModel
{
    Q_OBJECT
public:
    enum Role {
        FilterTextRole = Qt::UserRole + 100, // QString: names, address
        MovingRole,                          // bool: moving or jogging now
        AxesRole,                            // QVariantList of Axis::index() of the row
    };

    explicit AxisRowFilter(QObject* parent = nullptr);

    void setText(const QString& text);
    QString text() const { return m_text; }
    void setMovingFirst(bool on);
    bool movingFirst() const { return m_movingFirst; }

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex& sourceParent) const override;
    bool lessThan(const QModelIndex& left, const QModelIndex& right) const override;

private:
    QString m_text;
    bool m_movingFirst = false;
};

} // namespace stepdeck::ui
