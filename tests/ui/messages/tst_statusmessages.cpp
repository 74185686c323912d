// The status bar's message line: every message has an owner that clears or replaces it,
// every message expires, the newest live one is shown, and the log keeps them all with their
// times, bounded.
#include "TestMain.h"
#include "messages/StatusMessages.h"
#include <QSignalSpy>
#include <QtTest>

using stepdeck::ui::StatusMessages;
using Owner = StatusMessages::Owner;

class TestStatusMessages : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void newest_isShown_andOwnerClearsOnlyItsOwn();
    void sameOwner_replaces();
    void layoutNotice_neverCoversAMachineMessage();
    void message_expires();
    void log_keepsEveryMessageWithItsTime();
    void log_isBounded_oldestDropped();
};

void TestStatusMessages::newest_isShown_andOwnerClearsOnlyItsOwn()
{
    StatusMessages m;
    m.show(Owner::Link, QStringLiteral("link lost: peer vanished"));
    m.show(Owner::Jog, QStringLiteral("jog refused: not connected"));
    QCOMPARE(m.currentText(), QStringLiteral("jog refused: not connected"));
    QVERIFY(m.currentLine().endsWith(QStringLiteral("  jog refused: not connected")));
    m.clear(Owner::Jog); // jogging works again
    QCOMPARE(m.currentText(), QStringLiteral("link lost: peer vanished"));
    m.clear(Owner::Link); // connected again
    QCOMPARE(m.currentText(), QString());
}

void TestStatusMessages::sameOwner_replaces()
{
    StatusMessages m;
    m.show(Owner::Request, QStringLiteral("NAK"));
    m.show(Owner::Link, QStringLiteral("link"));
    m.show(Owner::Request, QStringLiteral("timeout"));
    QCOMPARE(m.currentText(), QStringLiteral("timeout"));
    m.clear(Owner::Request);
    QCOMPARE(m.currentText(), QStringLiteral("link")); // the NAK is gone with it
}

// A page that scrolls after a resize is worth saying, but not over a position error or a stop
// that came a moment before (CI saw the layout notice hide a Nanotec drive's position error).
void TestStatusMessages::layoutNotice_neverCoversAMachineMessage()
{
    StatusMessages m;
    m.show(Owner::Layout, QStringLiteral("Position scrolls"), StatusMessages::Severity::Info);
    QCOMPARE(m.currentText(), QStringLiteral("Position scrolls")); // alone: shown
    m.show(Owner::Controller, QStringLiteral("drive 2 reports a position error"));
    m.show(Owner::Safety, QStringLiteral("Stop sent"), StatusMessages::Severity::Info);
    m.show(Owner::Layout, QStringLiteral("Position and Status scroll"),
           StatusMessages::Severity::Info); // newer, still behind
    QCOMPARE(m.currentText(), QStringLiteral("Stop sent"));
    QCOMPARE(m.log().constLast().text, QStringLiteral("Position and Status scroll")); // logged
    m.clear(Owner::Safety);
    QCOMPARE(m.currentText(), QStringLiteral("drive 2 reports a position error"));
    QCOMPARE(m.currentSeverity(), StatusMessages::Severity::Error);
    m.clear(Owner::Controller);
    QCOMPARE(m.currentText(), QStringLiteral("Position and Status scroll"));
}

void TestStatusMessages::message_expires()
{
    StatusMessages m;
    QSignalSpy changed(&m, &StatusMessages::changed);
    m.show(Owner::Request, QStringLiteral("old error"), StatusMessages::Severity::Error, 50);
    m.show(Owner::Link, QStringLiteral("lives longer"), StatusMessages::Severity::Error, 60000);
    m.show(Owner::Setup, QStringLiteral("newest, short"), StatusMessages::Severity::Info, 80);
    QCOMPARE(m.currentText(), QStringLiteral("newest, short"));
    QTRY_COMPARE(m.currentText(), QStringLiteral("lives longer"));
    QVERIFY(changed.count() >= 4); // three shows and the expiry
}

void TestStatusMessages::log_keepsEveryMessageWithItsTime()
{
    StatusMessages m;
    QSignalSpy logged(&m, &StatusMessages::logged);
    const QDateTime before = QDateTime::currentDateTime();
    m.show(Owner::Link, QStringLiteral("link lost"));
    m.show(Owner::Setup, QStringLiteral("Written: Start speed."), StatusMessages::Severity::Info);
    m.clearAll(); // the line is empty again; the log is not
    QCOMPARE(m.currentText(), QString());
    QCOMPARE(logged.count(), 2);
    const QList<StatusMessages::LogEntry>& log = m.log();
    QCOMPARE(log.size(), 2);
    QCOMPARE(log.at(0).text, QStringLiteral("link lost"));
    QCOMPARE(log.at(0).severity, StatusMessages::Severity::Error);
    QCOMPARE(log.at(1).severity, StatusMessages::Severity::Info);
    QVERIFY(log.at(0).time >= before && log.at(1).time >= log.at(0).time);
    QVERIFY(log.at(1).time <= QDateTime::currentDateTime());
    // Date and time: a log read the next morning still says when.
    QCOMPARE(StatusMessages::logLine(log.at(0)),
             log.at(0).time.toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")) +
                 QStringLiteral("  link lost"));
}

void TestStatusMessages::log_isBounded_oldestDropped()
{
    StatusMessages m;
    const int total = StatusMessages::kLogLimit + 7;
    for (int i = 0; i < total; ++i)
        m.show(Owner::General, QStringLiteral("message %1").arg(i));
    QCOMPARE(m.log().size(), StatusMessages::kLogLimit);
    QCOMPARE(m.loggedCount(), quint64(total));
    QCOMPARE(m.log().constFirst().text, QStringLiteral("message 7"));
    QCOMPARE(m.log().constLast().text, QStringLiteral("message %1").arg(total - 1));
}

STEPDECK_TEST_MAIN(TestStatusMessages)
#include "tst_statusmessages.moc"
