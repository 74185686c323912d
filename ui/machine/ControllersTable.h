#pragma once
#include "EditorTable.h"

namespace stepdeck::ui {

// The machine editor's controllers: id, model (from the registry), port, the bus address map
// of multi-drive models ("X=1 Y=2", like the CLI's --axes) and the reset line of models that
// have one. Cells a model cannot use are disabled and empty.
// A controller's axes and the names they go by (the axes table's axis column offers them).
struct ControllerAxes
{
    QList<Axis> axes;
    AxisNames names;
};

class ControllersTable : public EditorTable
{
    Q_OBJECT
public:
    explicit ControllersTable(QWidget* parent = nullptr);

    void setControllers(const QList<machine::MachineController>& controllers);
    // The controllers as typed; false with *error naming the cell when a text is no value
    // (the rest is MachineFile::validate's).
    bool read(QList<machine::MachineController>* out, machine::MachineFileError* error) const;
    QStringList ids() const;
    // The controller axes of each id: the keys of its bus address map, else its model's axes.
    QMap<QString, ControllerAxes> controllerAxes() const;

    void addController(); // a new row with an unused id, the first model, port "sim"
    void removeCurrentController();

Q_SIGNALS:
    // An id was edited: axes that named the old id follow it.
    void idRenamed(const QString& from, const QString& to);
    void idsChanged();

private:
    void addRow(const machine::MachineController& c);
    void applyModel(int row); // enables the cells the row's model can use
};

// "X=1 Y=2", "feeder=5 gate=6" <-> bus address map and names (assignBusAxes); false with the
// reason when the text is not such a list.
QString busAddressText(const QMap<Axis, int>& addresses, const AxisNames& names);
bool parseBusAddresses(const QString& text, QMap<Axis, int>* addresses, AxisNames* names,
                       QString* error = nullptr);

} // namespace stepdeck::ui
