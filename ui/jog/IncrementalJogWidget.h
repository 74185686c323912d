#pragma once
#include <QGroupBox>
#include <QMap>

class QComboBox;
class QDoubleSpinBox;
class QGridLayout;
class QToolButton;

namespace stepdeck::ui {

class MachineContext;

// Incremental jog (issue 19): a size in each axis' unit (0.01, 0.1, 1, 10 mm, deg or steps,
// or a custom value) and +/- per machine axis, each a relative Machine::move (refused with a
// reason, nothing sent: refused()). Every connection is a machine (issue 28, item 0).
class IncrementalJogWidget : public QGroupBox
{
    Q_OBJECT
public:
    explicit IncrementalJogWidget(MachineContext* context, QWidget* parent = nullptr);

    double unitStepSize() const;        // in each axis' unit
    void setUnitStepSize(double units); // selects a preset or the custom value
    QToolButton* machineButton(const QString& axis, int sign) const;

public Q_SLOTS:
    void rebuild();
    void jogMachineAxis(const QString& axis, int sign);

Q_SIGNALS:
    void refused(const QString& reason);

private:
    QToolButton* makeButton(const QString& axis, int sign);

    MachineContext* m_context;
    QComboBox* m_size;
    QDoubleSpinBox* m_customUnits;
    QGridLayout* m_grid;
    QMap<QString, QToolButton*> m_machineButtons; // "X+", "A-"
};

} // namespace stepdeck::ui
