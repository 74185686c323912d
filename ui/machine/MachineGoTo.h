#pragma once
#include <QList>
#include <QWidget>

class QCheckBox;
class QDoubleSpinBox;
class QGridLayout;
class QLabel;
class QPushButton;

namespace stepdeck::program {
class MachineWorkOffsets;
}

namespace stepdeck::ui {

class ElidedLabel;
class MachineContext;

// Go-to of machine axes in their units (issues 19 and 31): a target box per axis with a check
// that says whether the axis goes; the checked axes go together as one G0 line of its own
// through MachineMdi (issue 30: the same check and path as a program's G0), which refuses the
// whole line with the reason (nothing sent) unless every axis is referenced and its target
// within its soft limits. Changing a target by hand (typing, arrows, wheel) checks its axis;
// Enter in a target goes like the button. With a work zero set (program::MachineWorkOffsets) a
// target is in work coordinates of the active system, and the label says so ("Go to (work)"); the
// soft limits stay in machine coordinates. The line below says what happened, on one line
// (elided): "arrived" only for an axis whose controller confirmed it at its target, read
// after the move ended.
class MachineGoTo : public QWidget
{
    Q_OBJECT
public:
    MachineGoTo(MachineContext* context, program::MachineWorkOffsets* offsets,
                QWidget* parent = nullptr);

    QCheckBox* axisCheck(const QString& axis) const;      // nullptr: no such axis
    QDoubleSpinBox* targetBox(const QString& axis) const; // nullptr: no such axis
    QStringList checkedAxes() const;                      // in the machine's order
    void choose(const QStringList& axes);                 // checks these, unchecks the rest
    QPushButton* goButton() const { return m_go; }
    QString resultText() const;
    QString labelText() const;

public Q_SLOTS:
    void go(); // refused while its last go-to still moves (one at a time)

protected:
    bool eventFilter(QObject* watched, QEvent* event) override; // typing, Enter in a target

private:
    struct Row
    {
        QString axis;
        QCheckBox* check = nullptr;
        QDoubleSpinBox* target = nullptr;
    };
    struct Pending
    {
        QString axis;
        double machineTarget = 0; // the arrival is judged in machine coordinates
    };
    void rebuild();
    void updateUnits();
    void updateLabel();
    QString targetsText(bool withMachine) const;               // "X to 1.000 mm, Y to 2.000 mm"
    QString axisNames() const;                                 // of the go-to under way: "X, Y"
    void onEnded(quint64 id, bool ok, const QString& message); // MachineMdi::ended
    void readPositions(); // once the move ended: a status read per controller involved
    void judgeArrival();  // once every read finished

    MachineContext* m_context;
    program::MachineWorkOffsets* m_offsets;
    QLabel* m_label;
    QGridLayout* m_grid;
    QPushButton* m_go;
    ElidedLabel* m_result;
    QList<Row> m_rows;
    QList<Pending> m_pendingAxes;             // the axes of the go-to under way
    quint64 m_pending = 0;                    // its line (MachineMdi)
    bool m_moveStarted = false;               // its check passed and the run began
    QString m_movingText;                     // said once it did
    QList<quint64> m_reads;                   // status reads still to finish (request ids)
    bool m_readFailed = false;                // one of them failed
    QList<QMetaObject::Connection> m_confirm; // the reads that judge the arrival
};

} // namespace stepdeck::ui
