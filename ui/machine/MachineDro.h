#pragma once
#include <QMap>
#include <QWidget>

class QGridLayout;
class QLabel;
class QTimer;
class QComboBox;
class QToolButton;

namespace stepdeck::machine {
struct MachineAxis;
struct MachineAxisStatus;
} // namespace stepdeck::machine

namespace stepdeck::program {
class MachineWorkOffsets;
}

namespace stepdeck::ui {

class DroValueLabel;
class ElidedLabel;
class MachineContext;
class MachineMoveTracker;
struct MoveProfile;

// The read-out of a machine (issue 19): its logical axes in their units, from
// Machine::axisStatus -- the device's step count converted back, never a host-side fraction.
// mm and deg with 3 decimals, steps whole; marked by how the position is known (REFERENCED,
// ESTIMATED with "≈", UNKNOWN dimmed, NO LINK for a controller whose link is down) and MOVING
// while it moves; during a move of a controller that reports no position then (the E-LAB),
// where the axis probably is (≈, from the ramp parameters known in this session) or else
// where it is heading (→), never the target as if reached. Zero sets an axis' work origin at its
// position (program::MachineWorkOffsets; refused while unknown): the digits then show the work
// position, marked as known as the machine position it comes from, and the line below the machine
// position in units and the controller's count. Nothing widens a row: the digits fit their box, the
// badge is as wide as its longest word, the lines elide.
class MachineDro : public QWidget
{
    Q_OBJECT
public:
    MachineDro(MachineContext* context, program::MachineWorkOffsets* offsets,
               QWidget* parent = nullptr);
    ~MachineDro() override;

    QString displayedValue(const QString& axis) const; // the digits, for tests
    QString unitText(const QString& axis) const;
    QString stateText(const QString& axis) const;
    QString detailText(const QString& axis) const;
    QString messageText() const; // why a zero was refused
    static QStringList stateWords();

public Q_SLOTS:
    // False (the reason on the message line) while the axis' position is unknown.
    bool zeroAxis(const QString& axis);
    void clearOffsets();

private:
    struct Row
    {
        DroValueLabel* value = nullptr;
        QLabel* state = nullptr;
        ElidedLabel* detail = nullptr;
    };
    void rebuild();
    void refresh();
    void showAxis(const Row& row, const machine::MachineAxisStatus& status, bool linked);
    // A move without position read-back (MachineMoveTracker); false: not such a move.
    bool showMoveWithoutReadback(const Row& row, const machine::MachineAxisStatus& status);
    MoveProfile rampOf(const machine::MachineAxis& axis) const;
    QString countWord(const machine::MachineAxis& axis) const; // "steps" (laser: "units")
    QString unitOf(const machine::MachineAxis& axis) const;    // mm, deg, or the count's word
    void setState(const Row& row, const QString& word, const QString& style, bool dim,
                  const QString& tip);

    MachineContext* m_context;
    program::MachineWorkOffsets* m_offsets;
    QGridLayout* m_grid;
    QComboBox* m_system; // G54..G59: the coordinate system Zero, the digits and Go to use
    QToolButton* m_clear;
    ElidedLabel* m_message;
    QString m_refusedAxis; // the axis whose Zero the message line refuses, if any
    QMap<QString, Row> m_rows;
    MachineMoveTracker* m_moves;
    QTimer* m_moveTick; // the estimate advances between status reads
};

} // namespace stepdeck::ui
