#pragma once
#include "model/MachineStatus.h"
#include <QElapsedTimer>
#include <QWidget>
#include <optional>

class QGridLayout;
class QLabel;
class QTimer;
class QToolButton;

namespace stepdeck::ui {

class ConnectionGate;
class DroValueLabel;
class ElidedLabel;
class GoToWidget;
class MachineContext;
class MachineDro;
class MachineGoTo;
class ReferenceRunner;

// Digital read-out: per axis the work position in user units (large digits), the machine
// position in steps, and how it is known: REFERENCED (referenced and standing still),
// ESTIMATED (integrated from jog rates), MOVING, UNKNOWN, or NO LINK (the last value before
// the link ended, not current). During a positioning move on a model without position
// read-back the core already holds the target: the panel shows its own estimate of where the
// axis is (MoveEstimate, from the ramp parameters known in this session) marked with ≈,
// and the target separately; during a reference run it says so (REFERENCING). Zero sets the
// work origin at the current position. No text widens a row (issue 16): the digits fit their
// box, the state badge is as wide as its longest word, the line below elides.
class PositionPanel : public QWidget
{
    Q_OBJECT
public:
    explicit PositionPanel(MachineContext* context, QWidget* parent = nullptr);

    QString displayedValue(Axis axis) const; // the large digits, for tests
    QString stateText(Axis axis) const;
    QString detailText(Axis axis) const; // the line below: machine steps, or the target
    QString limitsText(Axis axis) const;
    GoToWidget* goTo() const { return m_goTo; }
    // The logical axes of a machine in their units; shown only while a machine is open.
    MachineDro* machineDro() const { return m_machineDro; }
    MachineGoTo* machineGoTo() const { return m_machineGoTo; }
    // The runner whose current axes the read-out shows as referencing.
    void setReferenceRunner(const ReferenceRunner* runner);
    // Every word the state badge can show, in the current language.
    static QStringList stateWords();

public Q_SLOTS:
    void zeroAxis(Axis axis);
    void clearOffsets();
    void editUnits();
    void editSoftLimits();

private:
    struct Row
    {
        DroValueLabel* value = nullptr; // digits and unit
        ElidedLabel* steps = nullptr;   // machine position, target or "referencing"
        QLabel* state = nullptr;
        ElidedLabel* limits = nullptr;
    };
    struct MoveTrack
    {
        bool active = false;
        qint64 from = 0;
        qint64 to = 0;
        QElapsedTimer clock;
    };
    void rebuild();
    void onStatus(const MachineStatus& status);
    void showAxis(Axis axis, const Row& row, const AxisStatus& a);
    // Estimated position of a move in progress; nullopt without a profile.
    std::optional<qint64> estimate(Axis axis, const MoveTrack& move) const;
    void setState(const Row& row, const QString& state, const QString& style, bool dim,
                  const QString& tip);

    MachineContext* m_context;
    QGridLayout* m_grid;
    QMap<Axis, Row> m_rows;
    QMap<Axis, qint64> m_idlePosition; // where each axis was when last seen standing
    QMap<Axis, MoveTrack> m_moves;
    QTimer* m_moveTick;
    ConnectionGate* m_gate;
    GoToWidget* m_goTo;
    MachineDro* m_machineDro = nullptr;
    MachineGoTo* m_machineGoTo = nullptr;
    const ReferenceRunner* m_referencing = nullptr;
};

} // namespace stepdeck::ui
