#pragma once
#include "model/Axis.h"
#include <QDialog>

class QCheckBox;
class QLabel;
class QSpinBox;

namespace stepdeck::ui {

class ElidedLabel;
class MachineContext;

// Soft limits per axis, in machine steps: on/off, minimum and maximum, and "here" buttons
// that take the current (referenced) position. Applied on OK; non-modal.
class SoftLimitsDialog : public QDialog
{
    Q_OBJECT
public:
    explicit SoftLimitsDialog(MachineContext* context, QWidget* parent = nullptr);

    void accept() override;

private:
    struct Row
    {
        QCheckBox* enabled = nullptr;
        QSpinBox* minimum = nullptr;
        QSpinBox* maximum = nullptr;
    };
    MachineContext* m_context;
    QMap<Axis, Row> m_rows;
    ElidedLabel* m_problem;
};

} // namespace stepdeck::ui
