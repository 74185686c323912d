#pragma once
#include "model/Axis.h"
#include <QGroupBox>

class QComboBox;
class QDoubleSpinBox;
class QGridLayout;
class QSpinBox;
class QToolButton;

namespace stepdeck::ui {

class MachineContext;

// Incremental jog: a step size (1, 10, 100, 1000 or a custom value) and +/- per axis, each a
// relative positioning move through the session. With a machine open (issue 19): a size in
// each axis' unit (0.01, 0.1, 1, 10 mm, deg or steps, or a custom value) and +/- per machine
// axis, each a relative Machine::move (refused with a reason, nothing sent: refused()).
class IncrementalJogWidget : public QGroupBox
{
    Q_OBJECT
public:
    explicit IncrementalJogWidget(MachineContext* context, QWidget* parent = nullptr);

    qint64 stepSize() const;
    void setStepSize(qint64 steps); // selects a preset or the custom value
    QToolButton* button(Axis axis, int sign) const;
    double unitStepSize() const; // with a machine: in each axis' unit
    QToolButton* machineButton(const QString& axis, int sign) const;

public Q_SLOTS:
    void rebuild();
    void jog(Axis axis, int sign);
    void jogMachineAxis(const QString& axis, int sign);

Q_SIGNALS:
    void refused(const QString& reason);

private:
    void fillSizes(bool machine);
    QToolButton* makeButton(const QString& axis, int sign);

    MachineContext* m_context;
    QComboBox* m_size;
    QSpinBox* m_custom;
    QDoubleSpinBox* m_customUnits;
    bool m_machineSizes = false;
    QGridLayout* m_grid;
    QMap<Axis, QToolButton*> m_minus;
    QMap<Axis, QToolButton*> m_plus;
    QMap<QString, QToolButton*> m_machineButtons; // "X+", "A-"
};

} // namespace stepdeck::ui
