#pragma once
#include "model/MachineStatus.h"
#include <QPointer>
#include <QWidget>

class QComboBox;
class QGridLayout;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace stepdeck::machine {
class Machine;
}

namespace stepdeck::ui {

class ElidedLabel;
class LedIndicator;
class MachineContext;
class MachineReferenceRows;
class ReferenceRunner;

// Referencing (homing): direction and order per axis (default Z first, then X and Y),
// "Reference all" and per-axis runs, progress, and which axes are referenced.
class ReferencePanel : public QWidget
{
    Q_OBJECT
public:
    explicit ReferencePanel(MachineContext* context, QWidget* parent = nullptr);

    ReferenceRunner* runner() const { return m_runner; }
    QMap<Axis, int> directions() const;
    QMap<Axis, int> order() const;
    QString messageText() const;
    MachineReferenceRows* machineRows() const { return m_machineRows; }

public Q_SLOTS:
    void referenceAll();
    void referenceAxis(Axis axis);
    void cancel();

private:
    struct Row
    {
        QComboBox* direction = nullptr;
        QSpinBox* order = nullptr;
        LedIndicator* led = nullptr;
        QPushButton* run = nullptr;
    };
    void rebuild();
    void store();
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
    ReferenceRunner* m_runner;
    QGridLayout* m_grid;
    QWidget* m_controllerRows = nullptr;
    QMap<Axis, Row> m_rows;
    QPushButton* m_all;
    QPushButton* m_cancel;
    QProgressBar* m_progress;
    ElidedLabel* m_message;
    MachineReferenceRows* m_machineRows;
    quint64 m_machineRun = 0;     // the machine's reference run under way (Machine::reference)
    QStringList m_machineRunAxes; // its axes; empty: all
    QPointer<machine::Machine> m_listenedMachine;
    QList<Axis> m_successAxes; // referenced by the last successful run, still referenced
};

} // namespace stepdeck::ui
