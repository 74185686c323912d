#pragma once
#include "controller/Controller.h"
#include "model/CommandResult.h"
#include <QGroupBox>
#include <QTimer>
#include <QVariantMap>

class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;

namespace stepdeck::ui {

class MachineContext;

// The closed-loop commissioning of one drive with an encoder, step by step as the manual asks
// (Nanotec 8.1; operations of model/ClosedLoop.h): 1 check the motor data and the encoder,
// 2 the calibration run for a newly connected motor, 3 the closed-loop reference run after
// every power-on, 4 closed loop on. Shown only for models with Capabilities::closedLoop.
//
// Runs 2 and 3 turn the motor: the manual's warning is shown first in a non-modal box and the
// motor turns only after the operator confirmed it (STOP and PANIC keep working meanwhile, and
// end a run at once). While a run is on, its progress is what the drive shows -- time, position
// and encoder position read back -- in a busy bar; the drive reports no percentage. Results are
// what the drive said in this connection; what it cannot report (calibrated since when?) is
// said to be unknown. Texts are one line each, elided with the full text in the tooltip.
class ClosedLoopPanel : public QGroupBox
{
    Q_OBJECT
public:
    explicit ClosedLoopPanel(MachineContext* context, QWidget* parent = nullptr);

    QComboBox* axisBox() const { return m_axis; }
    QComboBox* directionBox() const { return m_direction; }
    QPushButton* checkButton() const { return m_check; }
    QPushButton* calibrateButton() const { return m_calibrate; }
    QPushButton* referenceButton() const { return m_reference; }
    QPushButton* enableButton() const { return m_enable; }
    QPushButton* disableButton() const { return m_disable; }
    QPushButton* resetErrorButton() const { return m_resetError; }
    QProgressBar* progressBar() const { return m_progress; }
    // The full texts (the labels may show them elided).
    QString motorDataText() const;
    QString calibrationText() const;
    QString referenceText() const;
    QString closedLoopText() const;
    QString progressText() const;
    QString messageText() const;
    QString nextStepText() const;
    bool isBusy() const { return m_pending != 0; }

public Q_SLOTS:
    void check();
    void askCalibrate(); // warning first; the run starts on OK
    void askReference();
    void askEnable();
    void disable();
    void resetError();

private:
    enum class Step { None, Check, Calibrate, Reference, Enable, Disable, ResetError };
    void buildLayout();
    void connectParts();
    void confirmThen(const QString& title, const QString& text, std::function<void()> go);
    void send(Step step, const QString& operation, const QVariantMap& extra = {});
    void onResult(const CommandResult& result);
    void onCheck(const QVariantMap& value);
    void onState(const QVariantMap& state);
    void pollState();
    void showProgress(const QVariantMap& state);
    void showNextStep();
    void onModelChanged();
    void onLinkState(LinkState state);
    void clearTexts();
    void updateEnabled();
    QVariantMap axisArgs() const;

    MachineContext* m_context;
    QComboBox* m_axis;
    QComboBox* m_direction;
    QPushButton* m_check;
    QPushButton* m_calibrate;
    QPushButton* m_reference;
    QPushButton* m_enable;
    QPushButton* m_disable;
    QPushButton* m_resetError;
    QLabel* m_motorData;
    QLabel* m_calibration;
    QLabel* m_referenceState;
    QLabel* m_closedLoop;
    QLabel* m_progressText;
    QLabel* m_message;
    QLabel* m_next;
    QProgressBar* m_progress;
    QTimer m_poll{this};
    RequestId m_pending = 0; // the check, run or switch in flight
    Step m_step = Step::None;
    RequestId m_stateRequest = 0;
    std::optional<bool> m_motorDataFit; // from the last check of this axis
    QVariantMap m_state;                // the last closed-loop-state of this axis
};

} // namespace stepdeck::ui
