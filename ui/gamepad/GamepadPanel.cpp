#include "GamepadPanel.h"
#include "common/ElidedLabel.h"
#include "common/LedIndicator.h"
#include "gamepad/GamepadDevice.h"
#include "gamepad/GamepadJogSource.h"
#include "jog/JogAxisMap.h"
#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>

namespace stepdeck::ui {

namespace {
constexpr int kMaxStickAxes = 8;
}

GamepadPanel::GamepadPanel(GamepadJogSource* source, JogAxisMap* jogSlots, QWidget* parent)
    : QWidget(parent), m_source(source), m_slots(jogSlots), m_device(new ElidedLabel(this, 2)),
      m_deadmanLed(new LedIndicator(tr("Dead-man button held"), this)),
      m_enabled(new QCheckBox(tr("Jog with the gamepad"), this)), m_deadman(new QSpinBox(this)),
      m_deadZone(new QSpinBox(this)), m_calibrate(new QPushButton(tr("Calibrate"), this)),
      m_hint(new ElidedLabel(this, 3)), m_rawForm(new QFormLayout)
{
    // Reserved lines (the full text in the tooltip): a gamepad plugged in or a calibration
    // hint never moves the settings the operator is changing (issue 16).
    for (ElidedLabel* label : {m_device, m_hint})
        label->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    m_enabled->setChecked(source->isEnabled());
    m_deadman->setRange(0, 31);
    m_deadman->setValue(qMax(0, source->deadmanButton()));
    m_deadman->setToolTip(tr("Button that must be held for the sticks to move the machine"));
    m_deadZone->setRange(0, 50);
    m_deadZone->setSuffix(QStringLiteral(" %"));
    m_deadZone->setValue(qRound(source->response().deadZone * 100));

    auto* settings = new QGroupBox(tr("Settings"), this);
    auto* form = new QFormLayout(settings);
    form->addRow(m_enabled);
    form->addRow(tr("Dead-man button:"), m_deadman);
    form->addRow(tr("Dead zone:"), m_deadZone);

    auto* mapping = new QGroupBox(tr("Stick mapping"), this);
    auto* grid = new QGridLayout(mapping);
    int row = 0;
    for (JogSlot axis : allJogSlots()) {
        auto* combo = new QComboBox(mapping);
        combo->addItem(tr("not used"), -1);
        for (int i = 0; i < kMaxStickAxes; ++i)
            combo->addItem(tr("stick axis %1").arg(i), i);
        const StickBinding b = source->binding(axis);
        combo->setCurrentIndex(qMax(0, combo->findData(b.index)));
        auto* invert = new QCheckBox(tr("invert"), mapping);
        invert->setChecked(b.invert);
        auto apply = [this, axis, combo, invert] {
            m_source->setBinding(axis, {combo->currentData().toInt(), invert->isChecked()});
            m_source->saveSettings();
        };
        connect(combo, &QComboBox::currentIndexChanged, this, apply);
        connect(invert, &QCheckBox::toggled, this, apply);
        m_rowName.insert(axis, new QLabel(jogSlotKey(axis), mapping));
        grid->addWidget(m_rowName.value(axis), row, 0);
        grid->addWidget(combo, row, 1);
        grid->addWidget(invert, row, 2);
        m_binding.insert(axis, combo);
        m_invert.insert(axis, invert);
        ++row;
    }

    auto* raw = new QGroupBox(tr("Sticks"), this);
    raw->setLayout(m_rawForm);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_device);
    layout->addWidget(m_deadmanLed);
    layout->addWidget(settings);
    layout->addWidget(mapping);
    layout->addWidget(raw);
    layout->addWidget(m_calibrate);
    layout->addWidget(m_hint);
    layout->addStretch(1);

    connect(m_enabled, &QCheckBox::toggled, this, [this](bool on) {
        m_source->setEnabled(on);
        m_source->saveSettings();
    });
    connect(m_deadman, &QSpinBox::valueChanged, this, [this](int b) {
        m_source->setDeadmanButton(b);
        m_source->saveSettings();
    });
    connect(m_deadZone, &QSpinBox::valueChanged, this, [this](int v) {
        JogResponse r = m_source->response();
        r.deadZone = v / 100.0;
        m_source->setResponse(r);
        m_source->saveSettings();
    });
    if (m_slots)
        connect(m_slots, &JogAxisMap::changed, this, &GamepadPanel::nameRows);
    nameRows();
    connect(m_calibrate, &QPushButton::clicked, this, &GamepadPanel::toggleCalibration);
    connect(source, &GamepadJogSource::stateChanged, this, &GamepadPanel::refresh);
    refresh();
}

QString GamepadPanel::rowName(JogSlot slot) const
{
    const QLabel* label = m_rowName.value(slot);
    return label ? label->text() : QString();
}

void GamepadPanel::nameRows()
{
    // With a machine open a row moves the machine axis on its jog slot (JogAxisMap).
    for (auto it = m_rowName.cbegin(); it != m_rowName.cend(); ++it) {
        const QString name = m_slots ? m_slots->label(it.key()) : QString();
        it.value()->setText(name.isEmpty() ? jogSlotKey(it.key()) : name);
    }
}

QString GamepadPanel::deviceText() const
{
    return m_device->text();
}

void GamepadPanel::toggleCalibration()
{
    if (m_source->isCalibrating()) {
        m_source->finishCalibration();
        m_calibrate->setText(tr("Calibrate"));
        m_hint->setText(tr("Calibration saved."));
    } else {
        m_source->startCalibration();
        m_calibrate->setText(tr("Finish calibration"));
        m_hint->setText(tr("Leave the sticks at rest, then move each stick to all its ends "
                           "and press \"Finish calibration\". The machine does not move while "
                           "calibrating."));
    }
}

void GamepadPanel::refresh()
{
    GamepadDevice* device = m_source->device();
    if (!device || !device->backendError().isEmpty())
        m_device->setText(device ? device->backendError() : tr("No gamepad support."));
    else if (!device->isConnected())
        m_device->setText(tr("No gamepad connected. Plug one in; it is picked up at once."));
    else
        m_device->setText(tr("Connected: %1").arg(device->name()));
    m_deadmanLed->setOn(m_source->deadmanHeld());

    const int axes = device && device->isConnected() ? qMin(device->axisCount(), kMaxStickAxes) : 0;
    while (m_bars.size() > axes) {
        m_rawForm->removeRow(int(m_bars.size()) - 1);
        m_bars.removeLast();
    }
    while (m_bars.size() < axes) {
        auto* bar = new QProgressBar(this);
        bar->setRange(-100, 100);
        bar->setTextVisible(false);
        bar->setMaximumHeight(10);
        m_rawForm->addRow(tr("Axis %1").arg(m_bars.size()), bar);
        m_bars << bar;
    }
    for (int i = 0; i < m_bars.size(); ++i)
        m_bars[i]->setValue(qRound(device->axis(i) * 100));
}

} // namespace stepdeck::ui
