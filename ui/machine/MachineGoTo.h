#pragma once
#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace stepdeck::ui {

class ElidedLabel;
class MachineContext;
class MachineWorkOffsets;

// Go-to of one machine axis in its unit (issue 19): an absolute target as a G0 line of its own
// through MachineMdi (issue 30: the same check and path as a program's G0), which refuses it
// with the reason (nothing sent) unless the axis is referenced and the target within its soft
// limits. With a work zero set (MachineWorkOffsets) the target is in work coordinates of the
// active system, and the label says so ("Go to (work)"); the soft limits stay in machine
// coordinates. Enter in
// the target field goes like the button. The line below says what happened, on one line
// (elided): "arrived" only once the machine confirmed the arrival.
class MachineGoTo : public QWidget
{
    Q_OBJECT
public:
    MachineGoTo(MachineContext* context, MachineWorkOffsets* offsets, QWidget* parent = nullptr);

    QComboBox* axisCombo() const { return m_axis; }
    QDoubleSpinBox* targetBox() const { return m_target; }
    QPushButton* goButton() const { return m_go; }
    QString resultText() const;
    QString labelText() const;

public Q_SLOTS:
    void go(); // refused while its last go-to still moves (one at a time)

protected:
    bool eventFilter(QObject* watched, QEvent* event) override; // Enter in the target: go()

private:
    void rebuild();
    void updateUnit();
    void onEnded(quint64 id, bool ok, const QString& message); // MachineMdi::ended
    void judgeArrival(bool read); // after the status read that follows the move's end

    MachineContext* m_context;
    MachineWorkOffsets* m_offsets;
    QLabel* m_label;
    QComboBox* m_axis;
    QDoubleSpinBox* m_target;
    QPushButton* m_go;
    ElidedLabel* m_result;
    QString m_pendingAxis;             // the axis of the go-to under way
    double m_pendingTarget = 0;        // its target in machine coordinates (the axis' unit)
    quint64 m_pending = 0;             // its line (MachineMdi)
    bool m_moveStarted = false;        // its check passed and the run began
    QString m_movingText;              // said once it did
    QMetaObject::Connection m_confirm; // the status read that judges the arrival
};

} // namespace stepdeck::ui
