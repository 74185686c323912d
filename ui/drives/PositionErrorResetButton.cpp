#include "PositionErrorResetButton.h"
#include "common/AxisRowFilter.h"
#include "drives/DrivePanel.h"
#include "machine/MachineContext.h"
#include <QAbstractItemView>
#include <QItemSelectionModel>

namespace stepdeck::ui {

PositionErrorResetButton::PositionErrorResetButton(MachineContext* context,
                                                   QAbstractItemView* drives, QWidget* parent)
    : QPushButton(tr("Reset position error"), parent), m_context(context), m_drives(drives)
{
    setObjectName(QStringLiteral("resetPositionErrorButton"));
    setToolTip(tr("For the drives selected above: take over the encoder position as the "
                  "position and clear the position error (manual 5.14)"));
    connect(this, &QPushButton::clicked, this, &PositionErrorResetButton::resetSelected);
    connect(m_drives->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &PositionErrorResetButton::updateEnabled);
    connect(m_drives->model(), &QAbstractItemModel::modelReset, this,
            &PositionErrorResetButton::updateEnabled);
    ControllerSession* session = context->session();
    connect(session, &ControllerSession::requestFinished, this,
            &PositionErrorResetButton::onResult);
    connect(session, &ControllerSession::linkStateChanged, this, [this] {
        m_pending.clear();
        updateEnabled();
    });
    updateEnabled();
}

QString PositionErrorResetButton::actionName()
{
    return tr("the \u201cReset position error\u201d button on the Drives page");
}

QList<Axis> PositionErrorResetButton::selectedAxes() const
{
    // The rows say which axes they are: the list may be filtered and sorted.
    QList<Axis> axes;
    for (const QModelIndex& row : m_drives->selectionModel()->selectedRows()) {
        for (const QVariant& index : row.data(AxisRowFilter::AxesRole).toList()) {
            if (const std::optional<Axis> axis = Axis::fromIndex(index.toInt()))
                axes << *axis;
        }
    }
    return axes;
}

void PositionErrorResetButton::updateEnabled()
{
    const bool ready = m_context->isConnected() && m_pending.isEmpty();
    setEnabled(ready && !selectedAxes().isEmpty());
}

void PositionErrorResetButton::resetSelected()
{
    for (Axis axis : selectedAxes()) {
        const RequestId id = m_context->session()->modelOperation(
            operationName(), {{operation::arg::kAxis, axisName(axis)}});
        m_pending.insert(id, axis);
    }
    updateEnabled();
}

void PositionErrorResetButton::onResult(const CommandResult& result)
{
    if (!m_pending.contains(result.id))
        return;
    const Axis axis = m_pending.take(result.id);
    Q_EMIT message(result.ok()
                       ? tr("Position error of axis %1 reset: its position is the encoder's now.")
                             .arg(m_context->controllerAxisName(axis))
                       : tr("Position error of axis %1 not reset: %2")
                             .arg(m_context->controllerAxisName(axis), result.message));
    updateEnabled();
}

} // namespace stepdeck::ui
