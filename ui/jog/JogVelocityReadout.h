#pragma once
#include <QGroupBox>
#include <QMap>

class QGridLayout;
class QLabel;

namespace stepdeck::ui {

class MachineContext;

// The live commanded jog velocity per axis. Without a machine: the controller's axes in its
// position unit per second (steps/s). With a machine open (issue 19): every axis of the
// machine by its name, in its own unit/s (mm/s, deg/s, steps/s), read from the status of the
// controller that drives it.
class JogVelocityReadout : public QGroupBox
{
    Q_OBJECT
public:
    explicit JogVelocityReadout(MachineContext* context, QWidget* parent = nullptr);

    // The shown value and unit of an axis ("X", or a machine axis' name); empty if not shown.
    QString valueText(const QString& axis) const;
    QString unitText(const QString& axis) const;

public Q_SLOTS:
    void rebuild();
    void refresh();

private:
    void addRow(const QString& axis, const QString& unit);

    struct Row
    {
        QLabel* value = nullptr;
        QLabel* unit = nullptr;
    };
    MachineContext* m_context;
    QGridLayout* m_grid;
    QMap<QString, Row> m_rows;
};

} // namespace stepdeck::ui
