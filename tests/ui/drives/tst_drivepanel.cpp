// Drive list: every drive of a Nanotec machine with its per-drive status; a drive that goes
// silent is marked while the others keep answering; the dock exists only for multi-drive
// models.
#include "../NanotecUiFixture.h"
#include "TestMain.h"
#include "common/AxisListBar.h"
#include "common/AxisRowFilter.h"
#include "drives/DriveListModel.h"
#include "drives/DrivePanel.h"
#include <QCheckBox>
#include <QDockWidget>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableView>
#include <QTableWidget>

using namespace stepdeck;
using namespace stepdeck::test;

class TestDrivePanel : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup() { m_f.reset(); }

    void driveList_showsThreeDrivesWithAxes();
    void driveList_silentDriveMarkedRed();
    void driveList_sixNamedDrives_showsTheirNames();
    void driveList_sameStatus_tableNotRebuilt();
    void driveList_filterByNameOrAddress_movingFirstOnRequest();
    void driveList_reconnect_showsDrivesAgain();
    void scan_listsDrivesOnTheBus();
    void scan_showsProgressAndCanBeCancelled();
    void disconnect_clearsDriveList();
    void dock_hiddenForSingleBoardModel();

private:
    ui::DrivePanel* panel() const { return m_f->window->drivePanel(); }
    QAbstractItemModel* list() const { return panel()->driveTable()->model(); }
    int rows() const { return list()->rowCount(); }
    QString text(int row, int column) const { return list()->index(row, column).data().toString(); }
    void reconnectSixNamedDrives()
    {
        m_f.reset();
        m_f = std::make_unique<NanotecUiFixture>();
        m_f->window->show();
        QVERIFY(m_f->connectNanotec(NanotecUiFixture::sixNamedDrives()));
    }
    std::unique_ptr<NanotecUiFixture> m_f;
};

void TestDrivePanel::init()
{
    QSettings().clear();
    m_f = std::make_unique<NanotecUiFixture>();
    m_f->window->show();
    QVERIFY(m_f->connectNanotec());
    QTRY_VERIFY_WITH_TIMEOUT(m_f->statusCount > 2, 5000);
}

void TestDrivePanel::driveList_showsThreeDrivesWithAxes()
{
    QTRY_COMPARE(rows(), 3);
    QCOMPARE(text(0, ui::DriveListModel::Address), QStringLiteral("1"));
    QCOMPARE(text(0, ui::DriveListModel::Axes), QStringLiteral("X"));
    QCOMPARE(text(2, ui::DriveListModel::Address), QStringLiteral("3"));
    QCOMPARE(text(2, ui::DriveListModel::Axes), QStringLiteral("Z"));
    QCOMPARE(panel()->silentCount(), 0);
    QVERIFY(!m_f->window->findChild<QDockWidget*>(QStringLiteral("drivesDock"))->isHidden());
}

void TestDrivePanel::driveList_silentDriveMarkedRed()
{
    QTRY_COMPARE(rows(), 3);
    QVERIFY(m_f->withBus([](nanotec::NanotecSimulator* s) { s->setDriveSilent(2, true); }));
    QTRY_COMPARE_WITH_TIMEOUT(panel()->silentCount(), 1, 10000);
    const QModelIndex silent = list()->index(1, ui::DriveListModel::Responding);
    QVERIFY(silent.data().toString().contains(QStringLiteral("NOT RESPONDING")));
    QCOMPARE(silent.data(Qt::BackgroundRole).value<QColor>(), QColor(0xc6, 0x28, 0x28));
    QVERIFY(!text(0, ui::DriveListModel::Responding).contains(QStringLiteral("NOT")));
    QVERIFY(!text(2, ui::DriveListModel::Responding).contains(QStringLiteral("NOT")));

    QVERIFY(m_f->withBus([](nanotec::NanotecSimulator* s) { s->setDriveSilent(2, false); }));
    QTRY_COMPARE_WITH_TIMEOUT(panel()->silentCount(), 0, 10000);
}

// Issue 32: six drives on one bus, named as the plant calls them: each row shows its drive's
// name, and the sixth (an axis past the four letters) is polled and marked when it is silent.
void TestDrivePanel::driveList_sixNamedDrives_showsTheirNames()
{
    reconnectSixNamedDrives();
    QTRY_COMPARE_WITH_TIMEOUT(rows(), 6, 5000);
    const QStringList names{"feeder", "gate", "press", "lift", "tilt", "stacker"};
    for (int r = 0; r < 6; ++r) {
        QCOMPARE(text(r, ui::DriveListModel::Address), QString::number(r + 1));
        QCOMPARE(text(r, ui::DriveListModel::Axes), names.at(r));
    }
    QCOMPARE(panel()->silentCount(), 0);
    QVERIFY(m_f->withBus([](nanotec::NanotecSimulator* s) { s->setDriveSilent(6, true); }));
    QTRY_COMPARE_WITH_TIMEOUT(panel()->silentCount(), 1, 10000);
    QVERIFY(text(5, ui::DriveListModel::Responding).contains(QStringLiteral("NOT RESPONDING")));
    QVERIFY(!text(4, ui::DriveListModel::Responding).contains(QStringLiteral("NOT")));
}

// Every poll brings the same drives: the table keeps its items (rebuilding it and sizing its
// columns to the texts cost the idle GUI a tenth of its time, issue 21). A change is shown:
// driveList_silentDriveMarkedRed.
void TestDrivePanel::driveList_sameStatus_tableNotRebuilt()
{
    QTRY_COMPARE(rows(), 3);
    QSignalSpy changed(list(), &QAbstractItemModel::dataChanged);
    QSignalSpy reset(list(), &QAbstractItemModel::modelReset);
    const int from = m_f->statusCount;
    QTRY_VERIFY_WITH_TIMEOUT(m_f->statusCount - from >= 5, 5000);
    QCOMPARE(changed.count(), 0);
    QCOMPARE(reset.count(), 0);

    QVERIFY(m_f->withBus([](nanotec::NanotecSimulator* s) { s->setDriveSilent(2, true); }));
    QTRY_COMPARE_WITH_TIMEOUT(panel()->silentCount(), 1, 10000);
    QVERIFY(text(1, ui::DriveListModel::Responding).contains(QStringLiteral("NOT RESPONDING")));
    QVERIFY(changed.count() > 0);
    QCOMPARE(reset.count(), 0);
}

// Issue 32, step 5: a bus of many drives is found by name or address, and lists the moving
// ones first when the operator asks for it (off by default: a row about to be picked does not
// jump away). "Moving" is what the device reports: the drive is active at the simulator.
void TestDrivePanel::driveList_filterByNameOrAddress_movingFirstOnRequest()
{
    reconnectSixNamedDrives();
    QTRY_COMPARE_WITH_TIMEOUT(rows(), 6, 5000);
    ui::AxisListBar* bar = panel()->driveBar();
    bar->filterEdit()->setText(QStringLiteral("ST"));
    QCOMPARE(rows(), 1);
    QCOMPARE(text(0, ui::DriveListModel::Axes), QStringLiteral("stacker"));
    QCOMPARE(bar->countText(), QStringLiteral("1 of 6"));
    bar->filterEdit()->setText(QStringLiteral("5"));
    QCOMPARE(rows(), 1);
    QCOMPARE(text(0, ui::DriveListModel::Axes), QStringLiteral("tilt"));
    bar->filterEdit()->clear();
    QCOMPARE(rows(), 6);

    QVERIFY(!bar->movingFirstBox()->isChecked());
    const Axis tilt = Axis::at(4);
    m_f->window->context()->session()->velocityMove({{tilt, 400}});
    auto tiltActive = [this] {
        bool active = false;
        m_f->withBus([&](nanotec::NanotecSimulator* s) { active = s->drive(5)->isActive(); });
        return active;
    };
    QTRY_VERIFY_WITH_TIMEOUT(tiltActive(), 3000);
    QTRY_VERIFY_WITH_TIMEOUT(list()->index(4, 0).data(ui::AxisRowFilter::MovingRole).toBool(),
                             3000);
    QCOMPARE(text(0, ui::DriveListModel::Axes), QStringLiteral("feeder")); // not on request
    bar->movingFirstBox()->setChecked(true);
    QCOMPARE(text(0, ui::DriveListModel::Axes), QStringLiteral("tilt"));
    QCOMPARE(text(1, ui::DriveListModel::Axes), QStringLiteral("feeder"));

    m_f->window->context()->session()->stop();
    QTRY_VERIFY_WITH_TIMEOUT(!tiltActive(), 3000);
    QTRY_COMPARE_WITH_TIMEOUT(text(0, ui::DriveListModel::Axes), QStringLiteral("feeder"), 3000);
    QCOMPARE(text(4, ui::DriveListModel::Axes), QStringLiteral("tilt"));
}

// The table forgets what it showed with the link: the same drives after a reconnect are
// listed again.
void TestDrivePanel::driveList_reconnect_showsDrivesAgain()
{
    QTRY_COMPARE(rows(), 3);
    m_f->window->context()->disconnectFromController();
    QTRY_COMPARE(rows(), 0);
    QVERIFY(m_f->connectNanotec());
    QTRY_COMPARE_WITH_TIMEOUT(rows(), 3, 5000);
    QCOMPARE(text(2, ui::DriveListModel::Axes), QStringLiteral("Z"));
}

void TestDrivePanel::scan_listsDrivesOnTheBus()
{
    QVERIFY(panel()->scanButton()->isEnabled());
    panel()->scanRange(1, 5);
    QVERIFY(!panel()->scanButton()->isEnabled());
    QTRY_COMPARE_WITH_TIMEOUT(panel()->foundTable()->rowCount(), 3, 10000);
    QCOMPARE(panel()->foundTable()->item(1, ui::DrivePanel::FoundAddress)->text(),
             QStringLiteral("2"));
    QVERIFY(!panel()->foundTable()->item(0, ui::DrivePanel::FoundFirmware)->text().isEmpty());
    QTRY_VERIFY(panel()->scanButton()->isEnabled());
}

void TestDrivePanel::scan_showsProgressAndCanBeCancelled()
{
    QVERIFY(m_f->withBus([](nanotec::NanotecSimulator* s) { s->clearReceivedFrames(); }));
    panel()->scanBus(); // 1..254, chunk by chunk
    QVERIFY(panel()->isScanning());
    QVERIFY(panel()->cancelScanButton()->isEnabled());
    QCOMPARE(panel()->scanProgress()->maximum(), 254);
    // The first chunk (1..16) holds the three drives.
    QTRY_VERIFY_WITH_TIMEOUT(panel()->scanProgress()->value() >= ui::DrivePanel::kScanChunk, 10000);
    QCOMPARE(panel()->foundTable()->rowCount(), 3);
    panel()->cancelScanButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(!panel()->isScanning(), 10000);
    QVERIFY2(panel()->scanState().contains(QStringLiteral("cancelled")),
             qPrintable(panel()->scanState()));
    QCOMPARE(panel()->foundTable()->rowCount(), 3); // what was found stays
    QVERIFY(panel()->scanButton()->isEnabled());
    QVERIFY(!panel()->cancelScanButton()->isEnabled());
    // The bus was asked no further than the chunk in flight when it was cancelled.
    const int stoppedAt = panel()->scanProgress()->value();
    QVERIFY(stoppedAt < 254);
    QList<QByteArray> frames;
    QVERIFY(m_f->withBus([&](nanotec::NanotecSimulator* s) { frames = s->receivedFrames(); }));
    int highest = 0;
    for (const QByteArray& f : frames) {
        if (f.endsWith("v") || f.endsWith("v\r")) {
            bool ok = false;
            const int address = f.mid(1, f.indexOf('v') - 1).toInt(&ok);
            if (ok)
                highest = qMax(highest, address);
        }
    }
    QCOMPARE(highest, stoppedAt);
}

void TestDrivePanel::disconnect_clearsDriveList()
{
    QTRY_COMPARE(rows(), 3);
    m_f->window->context()->disconnectFromController();
    QTRY_COMPARE(rows(), 0);
    QVERIFY(!panel()->scanButton()->isEnabled());
}

void TestDrivePanel::dock_hiddenForSingleBoardModel()
{
    m_f->window->context()->disconnectFromController();
    m_f->window->context()->selectModel(QStringLiteral("elab"));
    QTRY_VERIFY(m_f->window->findChild<QDockWidget*>(QStringLiteral("drivesDock"))->isHidden());
    bool listed = false;
    for (const auto& page : m_f->window->pages())
        listed = listed || page.first == QLatin1String("drives");
    QVERIFY(!listed);
}

STEPDECK_TEST_MAIN(TestDrivePanel)
#include "tst_drivepanel.moc"
