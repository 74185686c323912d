#pragma once
#include "model/Axis.h"
#include <QGroupBox>

class QComboBox;
class QGridLayout;
class QSpinBox;
class QToolButton;

namespace stepdeck::ui {

class MachineContext;

// Incremental jog: a step size (1, 10, 100, 1000 or a custom value) and +/- per axis, each a
// relative positioning move through the session.
class IncrementalJogWidget : public QGroupBox
{
    Q_OBJECT
public:
    explicit IncrementalJogWidget(MachineContext* context, QWidget* parent = nullptr);

    qint64 stepSize() const;
    void setStepSize(qint64 steps); // selects a preset or the custom value
    QToolButton* button(Axis axis, int sign) const;

public Q_SLOTS:
    void rebuild();
    void jog(Axis axis, int sign);

private:
    MachineContext* m_context;
    QComboBox* m_size;
    QSpinBox* m_custom;
    QGridLayout* m_grid;
    QMap<Axis, QToolButton*> m_minus;
    QMap<Axis, QToolButton*> m_plus;
};

} // namespace stepdeck::ui
