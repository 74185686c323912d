#include "JogSettingsWidget.h"
#include "jog/JogAxisMap.h"
#include "jog/JogController.h"
#include "jog/KeyboardJog.h"
#include "machine/MachineContext.h"
#include "machine/MachineDescription.h"
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QSettings>
#include <QSpinBox>

namespace stepdeck::ui {

JogSettingsWidget::JogSettingsWidget(MachineContext* context, JogController* jog,
                                     KeyboardJog* keyboard, QWidget* parent)
    : QGroupBox(tr("Jog settings"), parent), m_context(context), m_jog(jog), m_keyboard(keyboard),
      m_form(new QFormLayout(this)), m_deadZone(new QSpinBox(this)), m_curve(new QComboBox(this)),
      m_keyboardSpeed(new QSpinBox(this))
{
    const QSettings settings;
    m_response.deadZone = settings.value(QStringLiteral("jog/deadZone"), 0.08).toDouble();
    m_response.exponent = settings.value(QStringLiteral("jog/exponent"), 2.0).toDouble();

    m_deadZone->setRange(0, 50);
    m_deadZone->setSuffix(QStringLiteral(" %"));
    m_deadZone->setValue(qRound(m_response.deadZone * 100));
    m_deadZone->setToolTip(tr("Deflection of the pad that gives no motion"));
    m_curve->addItem(tr("Linear"), 1.0);
    m_curve->addItem(tr("Quadratic (fine near centre)"), 2.0);
    m_curve->addItem(tr("Cubic (finest near centre)"), 3.0);
    m_curve->setCurrentIndex(qMax(0, m_curve->findData(m_response.exponent)));
    m_keyboardSpeed->setRange(1, 100);
    m_keyboardSpeed->setSuffix(QStringLiteral(" %"));
    m_keyboardSpeed->setValue(
        qRound(settings.value(QStringLiteral("jog/keyboardFraction"), 0.5).toDouble() * 100));
    m_keyboardSpeed->setToolTip(tr("Keyboard jog speed as a share of the max jog speed"));
    m_keyboard->setSpeedFraction(m_keyboardSpeed->value() / 100.0);

    m_form->addRow(tr("Dead zone:"), m_deadZone);
    m_form->addRow(tr("Response:"), m_curve);
    m_form->addRow(tr("Keyboard speed:"), m_keyboardSpeed);

    connect(m_deadZone, &QSpinBox::valueChanged, this, [this](int v) {
        m_response.deadZone = v / 100.0;
        storeResponse();
    });
    connect(m_curve, &QComboBox::currentIndexChanged, this, [this] {
        m_response.exponent = m_curve->currentData().toDouble();
        storeResponse();
    });
    connect(m_keyboardSpeed, &QSpinBox::valueChanged, this, [this](int v) {
        QSettings().setValue(QStringLiteral("jog/keyboardFraction"), v / 100.0);
        m_keyboard->setSpeedFraction(v / 100.0);
    });
    connect(context, &MachineContext::modelChanged, this, &JogSettingsWidget::rebuild);
    connect(jog->axisMap(), &JogAxisMap::changed, this, &JogSettingsWidget::rebuild);
    rebuild();
}

void JogSettingsWidget::storeResponse()
{
    QSettings settings;
    settings.setValue(QStringLiteral("jog/deadZone"), m_response.deadZone);
    settings.setValue(QStringLiteral("jog/exponent"), m_response.exponent);
    Q_EMIT responseChanged(m_response);
}

void JogSettingsWidget::rebuild()
{
    for (QWidget* w : std::as_const(m_axisRows))
        m_form->removeRow(w);
    m_axisRows.clear();
    addMachineRows();
}

void JogSettingsWidget::addMachineRows()
{
    // A machine's axes on the jog slots, each in its own unit/s, up to the file's maxJogSpeed
    // (or the controller's jog maximum in that unit).
    const JogAxisMap* map = m_jog->axisMap();
    int row = 0;
    for (JogSlot slot : map->jogSlots()) {
        const machine::MachineAxis* axis = map->machineAxis(slot);
        if (!axis)
            continue;
        auto* spin = new QDoubleSpinBox(this);
        spin->setDecimals(axis->unit == machine::AxisUnit::Step ? 0 : 2);
        spin->setRange(0, map->ceiling(slot));
        spin->setSuffix(QLatin1Char(' ') + rateUnitName(*axis));
        spin->setValue(map->maxSpeed(slot));
        spin->setToolTip(
            tr("Jog speed of axis %1 at full deflection and 100 % override").arg(axis->name));
        connect(spin, &QDoubleSpinBox::valueChanged, this,
                [this, slot](double v) { m_jog->setMaxSpeed(slot, v); });
        m_form->insertRow(row++, tr("Max %1:").arg(axis->name), spin);
        m_axisRows << spin;
    }
}

} // namespace stepdeck::ui
