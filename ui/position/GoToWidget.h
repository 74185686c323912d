#pragma once
#include "model/CommandResult.h"
#include "model/MachineStatus.h"
#include <QGroupBox>

class QLabel;
class QLineEdit;
class QPushButton;

namespace stepdeck::ui {

class ElidedLabel;
class MachineContext;

// "Go to position" (work coordinates in the axis' units; empty fields stay where they are)
// and "Go to work zero", for a referenced machine: both are absolute moves, so the session
// checks them against the soft limits and the core refuses axes whose position is unknown.
class GoToWidget : public QGroupBox
{
    Q_OBJECT
public:
    explicit GoToWidget(MachineContext* context, QWidget* parent = nullptr);

    QLineEdit* target(Axis axis) const { return m_targets.value(axis); }
    QPushButton* goButton() const { return m_go; }
    QPushButton* workZeroButton() const { return m_zero; }
    QString messageText() const;
    // Non-empty: why no target can be sent now (not connected, not referenced, moving).
    QString refusal() const;

public Q_SLOTS:
    void goToTargets();
    void goToWorkZero();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void rebuild();
    // After "Move accepted": the message is replaced once the move's axes stand still.
    void followMove(const MachineStatus& status);
    void refresh();
    void onResult(const CommandResult& result);
    void send(const AxisVector& machineTargets, const QString& what);

    MachineContext* m_context;
    QMap<Axis, QLineEdit*> m_targets;
    QWidget* m_fields;
    QPushButton* m_go;
    QPushButton* m_zero;
    ElidedLabel* m_message;
    RequestId m_pending = 0;
    QList<Axis> m_sentAxes;       // the axes of the move in flight
    QList<Axis> m_following;      // an accepted move whose end is awaited
    bool m_showingReason = false; // m_message holds refusal(), replaced when it changes
};

} // namespace stepdeck::ui
