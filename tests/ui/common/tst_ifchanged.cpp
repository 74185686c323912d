// The setters for panels that refresh on every status poll (issue 21, idle cost): the same
// value sends the widget nothing, a new value is set as before.
#include "EventCounter.h"
#include "TestMain.h"
#include "common/IfChanged.h"
#include <QEvent>
#include <QLabel>
#include <QtTest>

using namespace stepdeck::ui;
using stepdeck::test::EventCounter;

class TestIfChanged : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void toolTip_sentOnlyWhenChanged_data();
    void toolTip_sentOnlyWhenChanged();
    void styleSheet_repolishedOnlyWhenChanged_data();
    void styleSheet_repolishedOnlyWhenChanged();
};

void TestIfChanged::toolTip_sentOnlyWhenChanged_data()
{
    QTest::addColumn<QString>("shown");
    QTest::addColumn<QString>("next");
    QTest::addColumn<int>("changeEvents");
    QTest::newRow("same tip") << QStringLiteral("referenced") << QStringLiteral("referenced") << 0;
    QTest::newRow("new tip") << QStringLiteral("referenced") << QStringLiteral("not referenced")
                             << 1;
    QTest::newRow("tip cleared") << QStringLiteral("referenced") << QString() << 1;
    QTest::newRow("none, still none") << QString() << QString() << 0;
}

void TestIfChanged::toolTip_sentOnlyWhenChanged()
{
    QFETCH(QString, shown);
    QFETCH(QString, next);
    QFETCH(int, changeEvents);
    QLabel label;
    label.setToolTip(shown);
    EventCounter changes(&label, QEvent::ToolTipChange);
    setToolTipIfChanged(&label, next);
    QCOMPARE(changes.count, changeEvents);
    QCOMPARE(label.toolTip(), next);
}

void TestIfChanged::styleSheet_repolishedOnlyWhenChanged_data()
{
    QTest::addColumn<QString>("shown");
    QTest::addColumn<QString>("next");
    QTest::addColumn<int>("styleChanges");
    const QString amber = QStringLiteral("QLabel { background:#ffe082; }");
    const QString green = QStringLiteral("QLabel { background:#c8e6c9; }");
    QTest::newRow("same sheet") << amber << amber << 0;
    QTest::newRow("new sheet") << amber << green << 1;
    QTest::newRow("sheet cleared") << amber << QString() << 1;
}

void TestIfChanged::styleSheet_repolishedOnlyWhenChanged()
{
    QFETCH(QString, shown);
    QFETCH(QString, next);
    QFETCH(int, styleChanges);
    QLabel label;
    label.setStyleSheet(shown);
    label.ensurePolished();
    EventCounter changes(&label, QEvent::StyleChange);
    setStyleSheetIfChanged(&label, next);
    QCOMPARE(changes.count > 0 ? 1 : 0, styleChanges);
    QCOMPARE(label.styleSheet(), next);
}

STEPDECK_TEST_MAIN(TestIfChanged)
#include "tst_ifchanged.moc"
