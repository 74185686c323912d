#pragma once
#include "model/MachineStatus.h"
#include <QWidget>

class QGridLayout;
class QLabel;
class QToolButton;

namespace stepdeck::ui {

class MachineContext;

// Digital read-out: per axis the work position in user units (large digits), the machine
// position in steps, and whether it is referenced, estimated (integrated from jog rates) or
// unknown. Zero sets the work origin at the current position.
class PositionPanel : public QWidget
{
    Q_OBJECT
public:
    explicit PositionPanel(MachineContext* context, QWidget* parent = nullptr);

    QString displayedValue(Axis axis) const; // the large digits, for tests
    QString stateText(Axis axis) const;

public Q_SLOTS:
    void zeroAxis(Axis axis);
    void clearOffsets();
    void editUnits();

private:
    struct Row
    {
        QLabel* value = nullptr;
        QLabel* unit = nullptr;
        QLabel* steps = nullptr;
        QLabel* state = nullptr;
    };
    void rebuild();
    void onStatus(const MachineStatus& status);

    MachineContext* m_context;
    QGridLayout* m_grid;
    QMap<Axis, Row> m_rows;
};

} // namespace stepdeck::ui
