// The jog panel's stopping distance (issue 28 item 6): from the jog speed set now (max speed x
// override) and the controller's jog ramp (the machine's jogAcceleration), in the axis' unit;
// in a label whose size never depends on its text (docs/architecture.md, "Main window
// layout"). No link is needed: the figures come from the description and the sessions' options.
#include "../UiTestSupport.h"
#include "TestMain.h"
#include "jog/JogAxisMap.h"
#include "jog/JogController.h"
#include "jog/JogStopDistanceLabel.h"
#include "machine/Machine.h"
#include <QVBoxLayout>

using namespace stepdeck;
using namespace stepdeck::test;

namespace {

machine::MachineAxis axis(const QString& name, const QString& controller, Axis on,
                          machine::AxisUnit unit, double stepsPerUnit, double maxJogSpeed)
{
    machine::MachineAxis a;
    a.name = name;
    a.controller = controller;
    a.axis = on;
    a.unit = unit;
    a.stepsPerUnit = stepsPerUnit;
    a.maxJogSpeed = maxJogSpeed;
    return a;
}

// An E-LAB table (X 400 steps/mm at 10 mm/s, Z 800 steps/mm at 5 mm/s) and a Nanotec rotary A.
machine::MachineDescription tableAndRotary()
{
    machine::MachineDescription d;
    d.name = QStringLiteral("Stop distance table");
    d.controllers = {{QStringLiteral("table"),
                      QStringLiteral("elab"),
                      QStringLiteral("sim"),
                      {},
                      {},
                      {},
                      {},
                      {}},
                     {QStringLiteral("rotary"),
                      QStringLiteral("nanotec"),
                      QStringLiteral("sim"),
                      {{Axis::X, 1}},
                      {},
                      {},
                      {},
                      {}}};
    d.axes = {axis("X", "table", Axis::X, machine::AxisUnit::Millimetre, 400, 10),
              axis("Z", "table", Axis::Z, machine::AxisUnit::Millimetre, 800, 5),
              axis("A", "rotary", Axis::X, machine::AxisUnit::Degree, 100, 90)};
    return d;
}

} // namespace

class TestJogStopDistance : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void machine_followsSpeedAndOverride_inTheAxisUnit();
    void singleElab_modelsDefaultRamp_inSteps();
    void size_doesNotDependOnTheText();
};

void TestJogStopDistance::machine_followsSpeedAndOverride_inTheAxisUnit()
{
    ui::MachineContext context;
    QString error;
    QVERIFY2(context.openMachine(tableAndRotary(), &error), qPrintable(error));
    ui::JogController jog(&context);
    ui::JogStopDistanceLabel label(&context, &jog);
    const ui::JogAxisMap* map = jog.axisMap();
    QCOMPARE(map->label(ui::JogSlot::PadHorizontal), QStringLiteral("X"));
    jog.setMaxSpeed(ui::JogSlot::PadHorizontal, 10);
    jog.setMaxSpeed(ui::JogSlot::ZStick, 5);
    jog.setOverride(1.0);
    // X sets the table's ramp (10^2 / 2 mm/s^2 x 400 = 20000 steps/s^2): 1 mm from 10 mm/s.
    // Z on the same ramp (the steeper of the two): 4000^2 / 40000 / 800 = 0.5 mm. A's drive
    // brakes by its own ramp: no figure.
    QCOMPARE(label.text(), QStringLiteral("Stops within X 1.00 mm, Z 0.50 mm"));
    QCOMPARE(label.objectName(), QStringLiteral("jogStopDistance"));
    // Half the override: a quarter of the distance.
    jog.setOverride(0.5);
    QVERIFY2(label.text().startsWith(QStringLiteral("Stops within X 0.25 mm, Z ")),
             qPrintable(label.text()));
    // A lower max speed of X alone.
    jog.setOverride(1.0);
    jog.setMaxSpeed(ui::JogSlot::PadHorizontal, 4);
    QVERIFY2(label.text().startsWith(QStringLiteral("Stops within X 0.16 mm")),
             qPrintable(label.text()));
}

void TestJogStopDistance::singleElab_modelsDefaultRamp_inSteps()
{
    ui::MachineContext context;
    context.selectModel(QStringLiteral("elab"));
    ui::JogController jog(&context);
    ui::JogStopDistanceLabel label(&context, &jog);
    jog.setMaxSpeed(ui::JogSlot::PadHorizontal, 1000);
    jog.setOverride(1.0);
    // The E-LAB's default host ramp, 2000 steps/s^2: 1000^2 / 4000 = 250 steps.
    QVERIFY2(label.text().startsWith(QStringLiteral("Stops within X 250 steps")),
             qPrintable(label.text()));
}

void TestJogStopDistance::size_doesNotDependOnTheText()
{
    ui::MachineContext context;
    QString error;
    QVERIFY2(context.openMachine(tableAndRotary(), &error), qPrintable(error));
    ui::JogController jog(&context);
    QWidget holder;
    auto* layout = new QVBoxLayout(&holder);
    auto* label = new ui::JogStopDistanceLabel(&context, &jog, &holder);
    layout->addWidget(label);
    holder.resize(260, 120);
    holder.show();
    QVERIFY(QTest::qWaitForWindowExposed(&holder));
    const QSize hint = label->sizeHint();
    const QRect geometry = label->geometry();
    jog.setMaxSpeed(ui::JogSlot::PadHorizontal, 10);
    jog.setOverride(0.01);
    const QString shortText = label->text();
    jog.setOverride(1.0);
    QVERIFY(label->text() != shortText);
    label->setText(label->text().repeated(6)); // far longer than the width
    QCoreApplication::processEvents();
    QCOMPARE(label->sizeHint(), hint);
    QCOMPARE(label->geometry(), geometry);
}

STEPDECK_TEST_MAIN(TestJogStopDistance)
#include "tst_jogstopdistance.moc"
