#pragma once
#include "common/ElidedLabel.h"
#include "controller/Controller.h"
#include "model/ModelPresentation.h"
#include "program/ProgramRunner.h"
#include <QWidget>

class QAction;
class QLabel;
class QHBoxLayout;
class QPushButton;

namespace stepdeck::ui {

class MachineContext;

// STOP and PANIC, always visible, plus the banner that says what the operator must do next
// (SafetyBanner: a machine that may still be moving first, then panic, setup, referencing).
// The buttons trigger the window's actions, whose keys (Esc, F1) work whatever widget has
// the focus (SafetyKeyFilter).
// A model without a stop command (Capabilities::stopCommand false): STOP and PANIC stay
// enabled -- they still end every jog input and cancel the host's queued work at once, which
// is what ends a chunked jog on such a model -- but their labels say "does not stop the
// controller", and Controller::noStopCommandText() -- or the model's own note, which names
// what stops its controller instead (EMIS: the reset input) -- stands permanently next to
// them. A disabled button would tell an operator in a hurry nothing; this tells where to reach.
class SafetyBar : public QWidget
{
    Q_OBJECT
public:
    SafetyBar(MachineContext* context, QAction* stop, QAction* panic, QAction* reference,
              QWidget* parent = nullptr);

    QPushButton* stopButton() const { return m_stop; }
    QPushButton* panicButton() const { return m_panic; }
    QString bannerText() const;
    QString bannerSeverity() const;
    QLabel* noStopNote() const { return m_noStop; }
    ElidedLabel* banner() const { return m_banner; }
    bool positionsLost() const { return m_positionsLost; }
    // The link ended while the last status showed motion, and no standstill was seen since.
    bool movingWhenLinkEnded() const { return m_movingWhenLinkEnded; }
    // Labels and the permanent note for a model's capabilities (called on every model and
    // link change with the context's). `presentation`: the model's own no-stop note, if any.
    void showCapabilities(const Capabilities& caps, const ModelPresentation& presentation = {});
    // A program's run and its line (ProgramPage::jobChanged): the banner says it runs or holds.
    void setJob(program::RunState state, int line);
    // A window's button in the row of STOP and PANIC, before "Reference all" (the job's "Show
    // jog pad", JobLayout): in that row's free width it takes no height from the jog pad.
    void addRowButton(QWidget* button);

private:
    void refresh();
    void onStatus(const MachineStatus& status);
    void onLinkState(LinkState state);
    void applyCapabilities();

    MachineContext* m_context;
    QPushButton* m_stop;
    QPushButton* m_panic;
    QPushButton* m_reference;
    QHBoxLayout* m_buttonRow = nullptr;
    ElidedLabel* m_banner;
    ElidedLabel* m_noStop;
    bool m_positionsLost = false;
    bool m_lastShowedMotion = false;
    bool m_movingWhenLinkEnded = false;
    bool m_hostPanicSent = false;
    bool m_sawPanic = false;
    bool m_hadReferenced = false; // some axis was referenced in this window's lifetime
    program::RunState m_job = program::RunState::Idle;
    int m_jobLine = 0;
};

} // namespace stepdeck::ui
