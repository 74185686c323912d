#pragma once
#include "ControllersTable.h"
#include "EditorTable.h"

namespace stepdeck::ui {

// The machine editor's axes: name (X..W), the controller and controller axis that drive it,
// unit, steps per unit, invert, optional soft limits and jog ceiling, reference direction and
// order. Columns are keyed by the file's field names ("softLimits" spans the min and max
// columns), so MachineFile::validate's error finds its cell.
class AxesTable : public EditorTable
{
    Q_OBJECT
public:
    explicit AxesTable(QWidget* parent = nullptr);

    void setAxes(const QList<machine::MachineAxis>& axes);
    // The axes as typed; false with *error naming the cell when a text is no number.
    bool read(QList<machine::MachineAxis>* out, machine::MachineFileError* error) const;
    QList<QWidget*> cells(int row, const QString& key) const override;

    // The controllers the controller column offers; cells keep their choice.
    void setControllerIds(const QStringList& ids);
    void renameController(const QString& from, const QString& to);
    // The axes each controller has (ControllersTable::controllerAxes): the axis column offers
    // those of the row's controller; a choice that is no longer offered stays, marked invalid.
    void setControllerAxes(const QMap<QString, ControllerAxes>& axes);

    void addAxis(); // the next free name on the first controller, counted in steps
    void removeCurrentAxis();

private:
    void addRow(const machine::MachineAxis& a);
    void addUnitCells(int row, const machine::MachineAxis& a);
    void addReferenceCells(int row, const machine::MachineAxis& a);
    void refreshAxisChoices(int row);
    bool readRow(int row, machine::MachineAxis* a, machine::MachineFileError* error) const;

    QStringList m_controllerIds;
    QMap<QString, ControllerAxes> m_controllerAxes;
};

} // namespace stepdeck::ui
