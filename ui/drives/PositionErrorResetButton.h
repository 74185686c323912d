#pragma once
#include "model/Axis.h"
#include "model/CommandResult.h"
#include "model/ModelOperations.h"
#include <QPushButton>

class QAbstractItemView;

namespace stepdeck::ui {

class MachineContext;

// "Reset position error" for the drives selected in the drive list (Nanotec 'D', manual
// 5.14: the position becomes the encoder's and the error is cleared), through the model
// operation operation::kResetPositionError. The core's messages name this button (actionName(),
// passed in ControllerOptions::actionNames by MachineContext) where the CLI names its command.
class PositionErrorResetButton : public QPushButton
{
    Q_OBJECT
public:
    PositionErrorResetButton(MachineContext* context, QAbstractItemView* drives,
                             QWidget* parent = nullptr);

    static QString operationName() { return operation::kResetPositionError; }
    // How messages name it: "the “Reset position error” button on the Drives page".
    static QString actionName();

Q_SIGNALS:
    void message(const QString& text);

private:
    void resetSelected();
    void onResult(const CommandResult& result);
    void updateEnabled();
    QList<Axis> selectedAxes() const;

    MachineContext* m_context;
    QAbstractItemView* m_drives; // rows with AxisRowFilter::AxesRole
    QMap<RequestId, Axis> m_pending;
};

} // namespace stepdeck::ui
