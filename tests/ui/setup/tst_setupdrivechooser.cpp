// The setup page on a bus of more drives than fit side by side (issue 32, step 5): the
// columns of the drives chosen by name or address, filled with what was read from them; a
// write goes to the drive shown (frames at the simulated bus); unwritten edits keep the
// columns until they are written.
#include "../NanotecUiFixture.h"
#include "TestMain.h"
#include "setup/ParameterField.h"
#include "setup/SetupDriveChooser.h"
#include "setup/SetupPage.h"
#include "setup/WritePreview.h"
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>

using namespace stepdeck;
using namespace stepdeck::test;
using ui::SetupDriveChooser;

class TestSetupDriveChooser : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void cleanup() { m_f.reset(); }

    void choose_firstMatchesByNameOrAddress_data();
    void choose_firstMatchesByNameOrAddress();
    void sixDrives_chosenDriveShowsItsReadValue_writeGoesToIt();
    void unwrittenEdit_keepsTheColumns();
    void threeDrives_noChooser();

private:
    void connect(const QString& bus);
    ui::SetupPage* page() const { return m_f->window->setupPage(); }
    ui::ParameterField* current(Axis axis) const
    {
        return page()->field(QStringLiteral("phase-current"), axis);
    }
    std::unique_ptr<NanotecUiFixture> m_f;
};

void TestSetupDriveChooser::connect(const QString& bus)
{
    QSettings().clear();
    m_f = std::make_unique<NanotecUiFixture>();
    m_f->window->show();
    QVERIFY(m_f->connectNanotec(bus));
    QTRY_VERIFY_WITH_TIMEOUT(page()->messageText().startsWith(QStringLiteral("Read ")), 20000);
}

void TestSetupDriveChooser::choose_firstMatchesByNameOrAddress_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QList<int>>("chosen"); // axis indices
    QTest::newRow("nothing typed: the first four") << QString() << QList<int>{0, 1, 2, 3};
    QTest::newRow("by name, any case") << QStringLiteral("STACK") << QList<int>{5};
    QTest::newRow("part of several names") << QStringLiteral("e") << QList<int>{0, 1, 2, 5};
    QTest::newRow("by address") << QStringLiteral("15") << QList<int>{4};
    QTest::newRow("no match") << QStringLiteral("zzz") << QList<int>{};
}

void TestSetupDriveChooser::choose_firstMatchesByNameOrAddress()
{
    QFETCH(QString, text);
    QFETCH(QList<int>, chosen);
    QList<Axis> axes;
    for (int i = 0; i < 6; ++i)
        axes << Axis::at(i);
    const QStringList names{"feeder", "gate", "press", "lift", "tilt", "stacker"};
    const QList<int> addresses{11, 12, 13, 14, 15, 16};
    QList<int> got;
    for (Axis a : SetupDriveChooser::choose(axes, names, addresses, text))
        got << a.index();
    QCOMPARE(got, chosen);
}

void TestSetupDriveChooser::sixDrives_chosenDriveShowsItsReadValue_writeGoesToIt()
{
    connect(NanotecUiFixture::sixNamedDrives());
    SetupDriveChooser* chooser = page()->driveChooser();
    QVERIFY(chooser->isVisibleTo(page()));
    QVERIFY(current(Axis::X) && current(Axis::U));
    QVERIFY(!current(Axis::at(5))); // stacker: not shown

    // The sixth drive holds 77 % (the default is 50 %); a read takes it from the device.
    m_f->session->sendRaw(QByteArrayLiteral("#6i77\r"));
    page()->read();
    QTRY_VERIFY_WITH_TIMEOUT(page()->messageText().startsWith(QStringLiteral("Read ")), 20000);
    chooser->filterEdit()->setText(QStringLiteral("stack"));
    QCOMPARE(chooser->shownAxes(), QList<Axis>{Axis::at(5)});
    QVERIFY(!current(Axis::X));
    QVERIFY(current(Axis::at(5)));
    QCOMPARE(current(Axis::at(5))->value().toLongLong(), qint64(77));
    QVERIFY(!current(Axis::at(5))->isChanged());

    QLineEdit* edit = current(Axis::at(5))->lineEdit();
    edit->selectAll();
    QTest::keyClicks(edit, QStringLiteral("60"));
    QVERIFY(m_f->withBus([](nanotec::NanotecSimulator* s) { s->clearReceivedFrames(); }));
    page()->writeButton()->click();
    QVERIFY(page()->openPreview());
    page()->openPreview()->accept();
    QTRY_VERIFY_WITH_TIMEOUT(page()->messageText().startsWith(QStringLiteral("Written")), 10000);
    QList<QByteArray> frames;
    QVERIFY(m_f->withBus([&](nanotec::NanotecSimulator* s) { frames = s->receivedFrames(); }));
    QVERIFY(frames.contains(QByteArray("#6i60\r")));
    static const QRegularExpression currentWrite(QStringLiteral("^#(\\d+)i\\d"));
    for (const QByteArray& f : std::as_const(frames)) {
        const QRegularExpressionMatch m = currentWrite.match(QString::fromLatin1(f));
        QVERIFY2(!m.hasMatch() || m.captured(1) == QLatin1String("6"), f.constData());
    }
}

void TestSetupDriveChooser::unwrittenEdit_keepsTheColumns()
{
    connect(NanotecUiFixture::sixNamedDrives());
    SetupDriveChooser* chooser = page()->driveChooser();
    QLineEdit* edit = current(Axis::Y)->lineEdit();
    edit->selectAll();
    QTest::keyClicks(edit, QStringLiteral("61"));
    QVERIFY(current(Axis::Y)->isChanged());
    chooser->filterEdit()->setText(QStringLiteral("tilt"));
    // Refused: the edit stays where it was, with the columns it belongs to.
    QVERIFY(page()->messageText().startsWith(QStringLiteral("Write or undo")));
    QCOMPARE(chooser->filterEdit()->text(), QString());
    QCOMPARE(chooser->shownAxes().first(), Axis::X);
    QVERIFY(current(Axis::Y));
    QCOMPARE(current(Axis::Y)->lineEdit()->text(), QStringLiteral("61"));
    QVERIFY(!current(Axis::at(4)));
}

void TestSetupDriveChooser::threeDrives_noChooser()
{
    connect(QStringLiteral("X=1,Y=2,Z=3"));
    QVERIFY(!page()->driveChooser()->isVisibleTo(page()));
    for (Axis a : {Axis::X, Axis::Y, Axis::Z})
        QVERIFY(current(a));
}

STEPDECK_TEST_MAIN(TestSetupDriveChooser)
#include "tst_setupdrivechooser.moc"
