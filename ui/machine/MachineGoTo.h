#pragma once
#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QPushButton;

namespace stepdeck::ui {

class ElidedLabel;
class MachineContext;

// Go-to of one machine axis in its unit (issue 19): an absolute target through Machine::move,
// which refuses it with the reason (nothing sent) unless the axis is referenced and the target
// within its soft limits. The line below says what happened, on one line (elided).
class MachineGoTo : public QWidget
{
    Q_OBJECT
public:
    explicit MachineGoTo(MachineContext* context, QWidget* parent = nullptr);

    QComboBox* axisCombo() const { return m_axis; }
    QDoubleSpinBox* targetBox() const { return m_target; }
    QPushButton* goButton() const { return m_go; }
    QString resultText() const;

public Q_SLOTS:
    void go();

private:
    void rebuild();
    void updateUnit();
    void onFinished(quint64 id, bool ok, const QString& message);

    MachineContext* m_context;
    QComboBox* m_axis;
    QDoubleSpinBox* m_target;
    QPushButton* m_go;
    ElidedLabel* m_result;
    quint64 m_pending = 0;
};

} // namespace stepdeck::ui
