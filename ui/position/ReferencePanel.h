#pragma once
#include "model/MachineStatus.h"
#include <QPointer>
#include <QWidget>

class QProgressBar;
class QPushButton;

namespace stepdeck::machine {
class Machine;
}

namespace stepdeck::ui {

class ElidedLabel;
class MachineContext;
class MachineReferenceRows;

// Referencing (homing) of the machine (every connection is one, issue 28 item 0): its axes
// with the direction and order of its description (MachineReferenceRows), "Reference all"
// (Machine::reference: every axis in that order) and per-axis runs, progress, and which axes
// are referenced.
class ReferencePanel : public QWidget
{
    Q_OBJECT
public:
    explicit ReferencePanel(MachineContext* context, QWidget* parent = nullptr);

    QString messageText() const;
    QProgressBar* progressBar() const { return m_progress; }
    bool isRunning() const { return m_machineRun != 0; }
    MachineReferenceRows* machineRows() const { return m_machineRows; }

public Q_SLOTS:
    void referenceAll();
    void cancel();
    // A STOP or PANIC from elsewhere ended the run: it says so (the machine's run fails too;
    // this is what the panel shows before that arrives).
    void stopped(const QString& message);

private:
    void referenceMachine(machine::Machine* m, const QStringList& axes);
    void showMachineOrNot();
    bool machineConnected() const;
    void listenTo(machine::Machine* m);
    void onStatus(const MachineStatus& status);
    void onProgress(int stage, int stages, const QString& text);
    void onFinished(bool ok, const QString& message);
    // The success message no longer holds: replace it with what happened.
    void invalidateSuccess(const QString& cause);

    MachineContext* m_context;
    QPushButton* m_all;
    QPushButton* m_cancel;
    QProgressBar* m_progress;
    ElidedLabel* m_message;
    MachineReferenceRows* m_machineRows;
    quint64 m_machineRun = 0;     // the machine's reference run under way (Machine::reference)
    QStringList m_machineRunAxes; // its axes; empty: all
    int m_groups = 1;             // its groups of equal order (the progress bar's range)
    int m_groupsStarted = 0;
    bool m_startingRun = false; // inside Machine::reference (its id not known yet)
    QPointer<machine::Machine> m_listenedMachine;
    QList<Axis> m_successAxes; // referenced by the last successful run, still referenced
};

} // namespace stepdeck::ui
