#pragma once
#include "model/Axis.h"
#include <QDialog>

class QDoubleSpinBox;
class QComboBox;

namespace stepdeck::ui {

class MachineContext;

// Steps per user unit (mm or degree) per axis; 0 shows plain steps.
class UnitsDialog : public QDialog
{
    Q_OBJECT
public:
    explicit UnitsDialog(MachineContext* context, QWidget* parent = nullptr);

    void accept() override;

private:
    MachineContext* m_context;
    QMap<Axis, QDoubleSpinBox*> m_steps;
    QMap<Axis, QComboBox*> m_unit;
};

} // namespace stepdeck::ui
