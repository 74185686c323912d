// The status bar's message line: every message has an owner that clears or replaces it,
// every message expires, the newest live one is shown, and the history keeps them all.
#include "main/StatusMessages.h"
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
    void message_expires();
    void history_keepsTheRecentMessages();
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

void TestStatusMessages::history_keepsTheRecentMessages()
{
    StatusMessages m;
    for (int i = 0; i < StatusMessages::kHistory + 3; ++i)
        m.show(Owner::General, QStringLiteral("message %1").arg(i));
    m.clearAll();
    QCOMPARE(m.currentText(), QString());
    const QStringList history = m.history();
    QCOMPARE(history.size(), StatusMessages::kHistory);
    QVERIFY(
        history.first().endsWith(QStringLiteral("message %1").arg(StatusMessages::kHistory + 2)));
}

QTEST_MAIN(TestStatusMessages)
#include "tst_statusmessages.moc"
