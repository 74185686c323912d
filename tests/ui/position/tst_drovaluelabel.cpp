// The DRO digits' box: the position panel sets its reserved text, digit type and unit on every
// status poll (20/s). The same values must neither re-lay out the panel nor repaint the
// digits (issue 21: three DRO repaints and a relayout of the position dock per poll); a new
// value does both as before.
#include "EventCounter.h"
#include "TestMain.h"
#include "position/DroValueLabel.h"
#include <QApplication>
#include <QVBoxLayout>
#include <QtTest>

using namespace stepdeck::ui;
using stepdeck::test::EventCounter;

namespace {
void deliverPosted()
{
    QCoreApplication::sendPostedEvents();
    QCoreApplication::processEvents();
}
} // namespace

class TestDroValueLabel : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void setter_sameValue_noRelayoutNoRepaint_data();
    void setter_sameValue_noRelayoutNoRepaint();
};

void TestDroValueLabel::setter_sameValue_noRelayoutNoRepaint_data()
{
    QTest::addColumn<QString>("setter");
    QTest::addColumn<bool>("change");
    QTest::addColumn<bool>("relayout");
    QTest::addColumn<bool>("repaint");
    QTest::newRow("reserved text, same") << "reserved" << false << false << false;
    QTest::newRow("reserved text, new") << "reserved" << true << true << true;
    QTest::newRow("digit font, same") << "font" << false << false << false;
    QTest::newRow("digit font, new") << "font" << true << true << true;
    QTest::newRow("unit, same") << "unit" << false << false << false;
    QTest::newRow("unit, new (the box keeps its size)") << "unit" << true << false << true;
}

void TestDroValueLabel::setter_sameValue_noRelayoutNoRepaint()
{
    QFETCH(QString, setter);
    QFETCH(bool, change);
    QFETCH(bool, relayout);
    QFETCH(bool, repaint);
    QWidget panel;
    auto* layout = new QVBoxLayout(&panel);
    auto* dro = new DroValueLabel(&panel);
    layout->addWidget(dro);
    QFont digits = panel.font();
    digits.setPointSizeF(digits.pointSizeF() * 2.6);
    dro->setDigitFont(digits);
    dro->setReservedText(QStringLiteral("\u2248-0000000"));
    dro->setUnit(QStringLiteral("steps"));
    dro->setText(QStringLiteral("0"));
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    deliverPosted();

    EventCounter layoutRequests(&panel, QEvent::LayoutRequest);
    EventCounter paints(dro, QEvent::Paint);
    if (setter == QLatin1String("reserved")) {
        dro->setReservedText(change ? QStringLiteral("\u2248-00000.000")
                                    : QStringLiteral("\u2248-0000000"));
    } else if (setter == QLatin1String("font")) {
        QFont next = digits;
        if (change)
            next.setPointSizeF(digits.pointSizeF() + 2);
        dro->setDigitFont(next);
    } else {
        dro->setUnit(change ? QStringLiteral("mm") : QStringLiteral("steps"));
    }
    deliverPosted();
    QCOMPARE(layoutRequests.count > 0, relayout);
    QCOMPARE(paints.count > 0, repaint);
}

STEPDECK_TEST_MAIN(TestDroValueLabel)
#include "tst_drovaluelabel.moc"
