#include "JogPanel.h"
#include "common/ConnectionGate.h"
#include "common/ElidedLabel.h"
#include "common/IfChanged.h"
#include "jog/IncrementalJogWidget.h"
#include "jog/JogAxisMap.h"
#include "jog/JogController.h"
#include "jog/JogSettingsWidget.h"
#include "jog/JogStopDistanceLabel.h"
#include "jog/JogVelocityReadout.h"
#include "jog/JoystickPad.h"
#include "jog/KeyboardJog.h"
#include "jog/PadJogSource.h"
#include "machine/MachineContext.h"
#include <QCheckBox>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QResizeEvent>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSlider>
#include <QTimer>
#include <QVBoxLayout>

namespace stepdeck::ui {

JogPanel::JogPanel(MachineContext* context, JogController* jog, KeyboardJog* keyboard,
                   QWidget* parent)
    : QWidget(parent), m_context(context), m_jog(jog), m_keyboard(keyboard),
      m_xy(new JoystickPad(JoystickPad::Mode::TwoAxis, this)),
      m_z(new JoystickPad(JoystickPad::Mode::Vertical, this)),
      m_u(new JoystickPad(JoystickPad::Mode::Vertical, this)), m_otherAxis(new QComboBox(this)),
      m_override(new QSlider(Qt::Horizontal, this)), m_overrideValue(new QLabel(this)),
      m_keyboardCheck(new QCheckBox(tr("Keyboard jog"), this)),
      m_keyboardState(new ElidedLabel(this)), m_refusal(new ElidedLabel(this, 2)),
      m_jogModeNote(new QLabel(this)), m_refusalTimer(new QTimer(this)),
      m_velocity(new JogVelocityReadout(context, this)),
      m_stopDistance(new JogStopDistanceLabel(context, jog, this)),
      m_incremental(new IncrementalJogWidget(context, this)), m_settingsDialog(new QDialog(this)),
      m_settings(new JogSettingsWidget(context, jog, keyboard, m_settingsDialog))
{
    setFocusPolicy(Qt::StrongFocus); // a focus target that is not a text field
    m_xy->setObjectName(QStringLiteral("jogPadXY"));
    m_z->setObjectName(QStringLiteral("jogStickZ"));
    m_u->setObjectName(QStringLiteral("jogStickU"));
    m_xy->setToolTip(tr("Drag the knob to jog X and Y; speed follows the deflection. Release "
                        "to stop (ramped)."));
    m_z->setToolTip(tr("Drag to jog Z; release to stop (ramped)."));
    m_padSources = {new PadJogSource(m_xy, JogSlot::PadHorizontal, JogSlot::PadVertical, this),
                    new PadJogSource(m_z, std::nullopt, JogSlot::ZStick, this),
                    new PadJogSource(m_u, std::nullopt, JogSlot::OtherStick, this)};
    for (PadJogSource* source : std::as_const(m_padSources)) {
        source->setResponse(m_settings->response());
        m_jog->addSource(source);
        connect(source, &PadJogSource::interrupted, this, &JogPanel::showRefusal);
    }

    auto* layout = new QHBoxLayout(this);
    auto* pads = new QHBoxLayout;
    pads->addWidget(m_xy, 3);
    pads->addWidget(m_z, 1);
    // The other stick with the machine axis it jogs below it (hidden without a machine: it
    // takes no room then).
    auto* other = new QVBoxLayout;
    other->addWidget(m_u, 1);
    other->addWidget(m_otherAxis);
    pads->addLayout(other, 1);
    m_otherAxis->setObjectName(QStringLiteral("jogStickAxis"));
    m_otherAxis->setFocusPolicy(Qt::NoFocus); // the arrows keep jogging
    m_otherAxis->setToolTip(tr("The machine axis this stick and End/Home jog"));
    m_otherAxis->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_otherAxis->setVisible(false);
    connect(m_otherAxis, &QComboBox::activated, this,
            [this] { m_jog->axisMap()->setOtherStickAxis(m_otherAxis->currentText()); });
    layout->addLayout(pads, 3);
    m_sideScroll = new QScrollArea(this);
    m_sideScroll->setObjectName(QStringLiteral("jogSideScroll"));
    m_sideScroll->setWidget(buildSidePanel());
    m_sideScroll->setWidgetResizable(true);
    m_sideScroll->setFrameShape(QFrame::NoFrame);
    m_sideScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    arrangeSide(false);
    layout->addWidget(m_sideScroll, 2);

    connect(m_settings, &JogSettingsWidget::responseChanged, this, [this](const JogResponse& r) {
        for (PadJogSource* source : std::as_const(m_padSources))
            source->setResponse(r);
    });
    connect(m_jog, &JogController::refused, this, &JogPanel::showRefusal);
    connect(m_incremental, &IncrementalJogWidget::refused, this, &JogPanel::showRefusal);
    connect(m_jog, &JogController::refusalEnded, m_refusal, &QLabel::clear);
    connect(m_context->session(), &ControllerSession::statusChanged, this, [this] { onStatus(); });
    connect(m_context, &MachineContext::modelChanged, this, &JogPanel::rebuild);
    connect(m_jog->axisMap(), &JogAxisMap::changed, this, &JogPanel::rebuild);
    connect(m_context, &MachineContext::machineStatusChanged, this, &JogPanel::onStatus);
    // Jogging needs a connection: the pads and step buttons say so by being disabled.
    m_gate = new ConnectionGate(m_context, this);
    for (QWidget* w : {static_cast<QWidget*>(m_xy), static_cast<QWidget*>(m_z),
                       static_cast<QWidget*>(m_u), static_cast<QWidget*>(m_incremental)})
        m_gate->add(w);
    connect(m_gate, &ConnectionGate::changed, this, &JogPanel::showKeyboardState);
    m_refusalTimer->setSingleShot(true);
    m_refusalTimer->setInterval(6000);
    connect(m_refusalTimer, &QTimer::timeout, m_refusal, &QLabel::clear);
    rebuild();
}

QString JogPanel::keyboardStateText() const
{
    return m_keyboardState->text();
}

QStringList JogPanel::keyboardStateTexts() const
{
    return {tr("Keyboard jog: off (Ctrl+J)"), tr("Keyboard jog: on, but not connected"),
            tr("Keyboard jog paused: the StepDeck window is not active"),
            tr("Keyboard jog paused: a text field has the focus, the arrows edit it. Click "
               "the jog panel to resume."),
            tr("Keyboard jog ON: %1").arg(KeyboardJog::keyLegend(slotLabels()))};
}

void JogPanel::showKeyboardState()
{
    enum { Off, NotConnected, Inactive, TextField, On };
    int state = On;
    if (!m_keyboardCheck->isChecked())
        state = Off;
    else if (!m_context->isConnected())
        state = NotConnected;
    else if (!m_keyboard->windowActive())
        state = Inactive;
    else if (m_keyboard->textFieldHasFocus())
        state = TextField;
    static const QString amber = QStringLiteral("color: #b26a00; font-weight: bold;");
    const QString style = state == Off  ? QStringLiteral("color: palette(dark);")
                          : state == On ? QStringLiteral("color: #1b5e20; font-weight: bold;")
                                        : amber;
    const QStringList texts = keyboardStateTexts();
    m_keyboardState->setReservedTexts(texts); // the legend follows the model's axes
    m_keyboardState->setText(texts.at(state));
    setStyleSheetIfChanged(m_keyboardState, QStringLiteral("QLabel { %1 }").arg(style));
}

void JogPanel::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    fitSide();
}

namespace {
// A column's height at a width (its texts wrap: the keyboard state, the stopping distance).
int heightAt(const QWidget* column, int width)
{
    const int atLeast = column->minimumSizeHint().height();
    return column->hasHeightForWidth()
               ? qMax(atLeast, column->heightForWidth(qMax(width, column->minimumWidth())))
               : atLeast;
}
} // namespace

void JogPanel::fitSide()
{
    // Side by side where one column does not fit the height (the Run workspace at 1366x768,
    // issue 31: every jog control visible without scrolling); the decision follows the height
    // only, so the width it asks never turns it back.
    const int spacing = m_sideGrid->verticalSpacing();
    const int columnWidth = m_sideScroll->viewport()->width();
    const int oneColumn = heightAt(m_sideA, columnWidth) + heightAt(m_sideB, columnWidth) +
                          heightAt(m_sideC, columnWidth) + 2 * spacing;
    // Only where the pads keep their room beside the columns (they are what the operator
    // holds); otherwise the column scrolls.
    auto* row = qobject_cast<QHBoxLayout*>(layout());
    const int padsMinimum = row ? row->itemAt(0)->minimumSize().width() : 0;
    const QMargins margins = contentsMargins() + (row ? row->contentsMargins() : QMargins());
    const int room =
        width() - margins.left() - margins.right() - padsMinimum - (row ? row->spacing() : 0);
    arrangeSide(oneColumn > m_sideScroll->height() && room >= sideWidth(true));
}

int JogPanel::sideWidth(bool sideBySide) const
{
    const auto least = [](const QWidget* w) {
        return qMax(w->minimumSizeHint().width(), w->minimumWidth());
    };
    const int a = least(m_sideA);
    const int b = least(m_sideB);
    const int c = least(m_sideC);
    const int content =
        sideBySide ? a + b + c + 2 * m_sideGrid->horizontalSpacing() : qMax(a, qMax(b, c));
    // Side by side nothing scrolls: no room for a scroll bar.
    return qMax(300, content + 6 +
                         (sideBySide ? 0 : m_sideScroll->verticalScrollBar()->sizeHint().width()));
}

void JogPanel::arrangeSide(bool sideBySide)
{
    if (sideBySide == m_sideBySide && m_sideGrid->indexOf(m_sideC) >= 0)
        return;
    m_sideBySide = sideBySide;
    m_sideGrid->removeWidget(m_sideB);
    m_sideGrid->removeWidget(m_sideC);
    m_sideGrid->addWidget(m_sideB, sideBySide ? 0 : 1, sideBySide ? 1 : 0);
    m_sideGrid->addWidget(m_sideC, sideBySide ? 0 : 2, sideBySide ? 2 : 0);
    m_sideGrid->setRowStretch(3, 1);
    // Never clip the controls (longer labels in German): the pads give way instead.
    m_sideScroll->setMinimumWidth(sideWidth(sideBySide));
    // Side by side, the columns share the width with the pads: each wide enough that its
    // texts need few lines.
    if (auto* row = qobject_cast<QHBoxLayout*>(layout()))
        row->setStretch(1, sideBySide ? 3 : 2);
}

QGroupBox* JogPanel::buildSpeedOverride(QWidget* parent)
{
    auto* speed = new QGroupBox(tr("Speed override"), parent);
    auto* speedRows = new QVBoxLayout(speed);
    auto* sv = new QHBoxLayout;
    speedRows->addLayout(sv);
    m_override->setRange(1, 100);
    m_override->setValue(QSettings().value(QStringLiteral("jog/override"), 100).toInt());
    m_override->setFocusPolicy(Qt::NoFocus);
    m_override->setToolTip(tr("Scales every jog speed (pad, keyboard, gamepad)"));
    m_overrideValue->setMinimumWidth(48);
    m_overrideValue->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    sv->addWidget(m_override, 1);
    sv->addWidget(m_overrideValue);
    auto applyOverride = [this](int percent) {
        m_overrideValue->setText(QStringLiteral("%1 %").arg(percent));
        m_jog->setOverride(percent / 100.0);
        QSettings().setValue(QStringLiteral("jog/override"), percent);
    };
    connect(m_override, &QSlider::valueChanged, this, applyOverride);
    applyOverride(m_override->value());
    // The stopping distance at this speed (issue 28 item 6), below the slider that sets it.
    speedRows->addWidget(m_stopDistance);
    return speed;
}

QWidget* JogPanel::buildSidePanel()
{
    auto* side = new QWidget(this);
    m_sideGrid = new QGridLayout(side);
    m_sideGrid->setContentsMargins(0, 0, 0, 0);
    // A: what the jog does (velocity, why it was refused, its settings); B: the override and
    // keyboard jog; C: steps. Side by side the columns share the height about evenly (1366x768
    // less a panel and a title bar, issue 31).
    m_sideA = buildJogColumn(side);
    m_sideB = buildKeyboardColumn(side);
    m_sideC = new QWidget(side);
    m_sideGrid->addWidget(m_sideA, 0, 0);
    auto* vc = new QVBoxLayout(m_sideC);
    vc->setContentsMargins(0, 0, 0, 0);
    m_incremental->setParent(m_sideC);
    vc->addWidget(m_incremental);
    vc->addStretch(1);
    return side;
}

QWidget* JogPanel::buildJogColumn(QWidget* parent)
{
    auto* column = new QWidget(parent);
    auto* v = new QVBoxLayout(column);
    v->setContentsMargins(0, 0, 0, 0);
    m_velocity->setParent(column);
    v->addWidget(m_velocity);
    m_refusal->setParent(column);
    m_refusal->setObjectName(QStringLiteral("jogRefusal"));
    // Two lines reserved, a longer reason elided (full text in the tooltip and the log).
    m_refusal->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    m_refusal->setStyleSheet(QStringLiteral("QLabel { color: #e53935; font-weight: bold; }"));
    v->addWidget(m_refusal);
    // Tuning lives in a dialog: the panel stays narrow enough for the pads.
    m_settingsDialog->setWindowTitle(tr("Jog settings"));
    auto* dialogLayout = new QVBoxLayout(m_settingsDialog);
    dialogLayout->addWidget(m_settings);
    auto* close = new QDialogButtonBox(QDialogButtonBox::Close, m_settingsDialog);
    connect(close, &QDialogButtonBox::rejected, m_settingsDialog, &QDialog::hide);
    dialogLayout->addWidget(close);
    auto* settingsButton = new QPushButton(tr("Jog settings\u2026"), column);
    settingsButton->setFocusPolicy(Qt::NoFocus);
    settingsButton->setToolTip(tr("Max jog speed per axis, dead zone, response curve, keyboard "
                                  "speed"));
    connect(settingsButton, &QPushButton::clicked, m_settingsDialog, &QDialog::show);
    v->addWidget(settingsButton);
    v->addStretch(1);
    return column;
}

QWidget* JogPanel::buildKeyboardColumn(QWidget* parent)
{
    auto* column = new QWidget(parent);
    auto* v = new QVBoxLayout(column);
    v->setContentsMargins(0, 0, 0, 0);
    v->addWidget(buildSpeedOverride(column));
    m_keyboardCheck->setParent(column);
    m_keyboardCheck->setFocusPolicy(Qt::NoFocus);
    m_keyboardCheck->setToolTip(tr("Arrows jog X/Y, Page Up/Down jog Z while this window is "
                                   "active and no text field has the focus (Ctrl+J)"));
    connect(m_keyboardCheck, &QCheckBox::toggled, this, [this](bool on) {
        m_keyboard->setEnabled(on);
        // Arrow keys typed into a text field stay there: take the focus so they jog.
        if (on)
            setFocus(Qt::OtherFocusReason);
        showKeyboardState();
    });
    connect(m_keyboard, &KeyboardJog::pausedChanged, this, &JogPanel::showKeyboardState);
    v->addWidget(m_keyboardCheck);
    // On or off, and which keys: on the panel itself, not only in a tooltip.
    m_keyboardState->setParent(column);
    m_keyboardState->setObjectName(QStringLiteral("keyboardJogState"));
    // The room of its longest state: the controls below never move (issue 16).
    m_keyboardState->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_keyboardState->setReservedTexts(keyboardStateTexts());
    v->addWidget(m_keyboardState);
    m_jogModeNote->setParent(column);
    m_jogModeNote->setObjectName(QStringLiteral("jogModeNote"));
    m_jogModeNote->setWordWrap(true);
    m_jogModeNote->setText(
        tr("This controller has no jog command: the pad, keys and gamepad move it by short "
           "targets, each sent only after the previous one arrived. Releasing ends jogging "
           "after the short move under way. Incremental jog moves by the step size."));
    v->addWidget(m_jogModeNote);
    v->addStretch(1);
    // Wide enough that the keyboard's longest state takes a few lines, not a tall column.
    column->setMinimumWidth(fontMetrics().averageCharWidth() * 28);
    return column;
}

QMap<JogSlot, QString> JogPanel::slotLabels() const
{
    QMap<JogSlot, QString> labels;
    const JogAxisMap* map = m_jog->axisMap();
    for (JogSlot slot : map->jogSlots())
        labels.insert(slot, map->label(slot));
    return labels;
}

void JogPanel::rebuild()
{
    releaseAll();
    m_jogModeNote->setVisible(m_jog->axisMap()->jogsByTargets());
    // The slots' axes: the machine's (JogAxisMap). Without a model chosen yet, the pad alone
    // (it moves nothing and says so when used).
    const QMap<JogSlot, QString> labels = slotLabels();
    const bool none = !m_context->hasMachine();
    m_xy->setVisible(labels.contains(JogSlot::PadHorizontal) || none);
    m_xy->setAxisLabels(labels.value(JogSlot::PadHorizontal, QStringLiteral("X")),
                        labels.contains(JogSlot::PadVertical) || none
                            ? labels.value(JogSlot::PadVertical, QStringLiteral("Y"))
                            : QString());
    m_z->setVisible(labels.contains(JogSlot::ZStick));
    m_u->setVisible(labels.contains(JogSlot::OtherStick));
    m_u->setAxisLabels(QString(), labels.value(JogSlot::OtherStick, QStringLiteral("U")));
    m_u->setToolTip(tr("Drag to jog %1; release to stop (ramped).")
                        .arg(labels.value(JogSlot::OtherStick, QStringLiteral("U"))));
    const QStringList choices = m_jog->axisMap()->otherStickChoices();
    {
        const QSignalBlocker blocker(m_otherAxis);
        m_otherAxis->clear();
        m_otherAxis->addItems(choices);
        m_otherAxis->setCurrentText(labels.value(JogSlot::OtherStick));
    }
    m_otherAxis->setVisible(!choices.isEmpty());
    showKeyboardState();
    // The velocity rows follow the axes: the side's columns once they are laid out.
    QMetaObject::invokeMethod(this, &JogPanel::fitSide, Qt::QueuedConnection);
}

void JogPanel::releaseAll()
{
    m_jog->releaseAll(); // latches every source: pads re-centre, held keys need a new press
}

void JogPanel::onStatus()
{
    // Each slot's axis, in its machine axis' unit/s.
    const JogAxisMap* map = m_jog->axisMap();
    auto slot = [&](JogSlot axis, double* fraction) {
        double v = 0.0;
        const AxisStatus status = map->slotStatus(axis, &v);
        const double max = m_jog->maxSpeed(axis);
        *fraction = max > 0 ? v / max : 0.0;
        return status.limitSwitch;
    };
    double x = 0, y = 0, z = 0, u = 0;
    m_xy->setLimitActive(0, slot(JogSlot::PadHorizontal, &x));
    m_xy->setLimitActive(1, slot(JogSlot::PadVertical, &y));
    m_z->setLimitActive(1, slot(JogSlot::ZStick, &z));
    m_u->setLimitActive(1, slot(JogSlot::OtherStick, &u));
    m_xy->setVelocityHint(QPointF(x, y));
    m_z->setVelocityHint(QPointF(0, z));
    m_u->setVelocityHint(QPointF(0, u));
}

void JogPanel::showRefusal(const QString& reason)
{
    m_refusal->setText(reason);
    m_refusalTimer->start();
}

QString JogPanel::keyboardLegend() const
{
    return KeyboardJog::keyLegend(slotLabels());
}

} // namespace stepdeck::ui
