// SerialPortAccess: the message for a serial port the user may not open (names the group to
// join) and the probe that gathers its facts from the device node and the user's groups.
#include "TestMain.h"
#include "transport/SerialPortAccess.h"
#include <QTemporaryFile>
#include <QtTest>
#include <grp.h>
#include <sys/stat.h>
#include <unistd.h>

using namespace stepdeck;

class TestSerialPortAccess : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void deniedText_data();
    void deniedText();
    void probe_ownFileWithoutRights_notAccessibleButInGroup();
    void probe_ownReadableFile_accessibleWithGroupName();
    void probe_missingDevice_groupUnknown_textNamesDialout();
};

void TestSerialPortAccess::deniedText_data()
{
    QTest::addColumn<bool>("accessible");
    QTest::addColumn<QString>("group");
    QTest::addColumn<bool>("inGroupNow");
    QTest::addColumn<bool>("groupListsUser");
    QTest::addColumn<QStringList>("mustContain");
    QTest::addColumn<QStringList>("mustNotContain");

    QTest::newRow("not a member: join dialout")
        << false << "dialout" << false << false
        << QStringList{"/dev/ttyUSB0", "access denied", "'dialout'", "sudo adduser alice dialout",
                       "log out and in again"}
        << QStringList{"in use"};
    QTest::newRow("other group named as it is")
        << false << "uucp" << false << false << QStringList{"'uucp'", "sudo adduser alice uucp"}
        << QStringList{"dialout"};
    QTest::newRow("group unknown: Debian's dialout")
        << false << "" << false << false << QStringList{"'dialout'", "sudo adduser alice dialout"}
        << QStringList{};
    QTest::newRow("joined but not logged in again")
        << false << "dialout" << false << true << QStringList{"'dialout'", "log out and in again"}
        << QStringList{"sudo adduser"};
    QTest::newRow("in the group, still denied: permissions")
        << false << "dialout" << true << true << QStringList{"ls -l /dev/ttyUSB0", "'dialout'"}
        << QStringList{"sudo adduser", "log out"};
    QTest::newRow("accessible: locked by another program")
        << true << "dialout" << false << false
        << QStringList{"/dev/ttyUSB0", "in use by another program"}
        << QStringList{"dialout", "access denied"};
}

void TestSerialPortAccess::deniedText()
{
    QFETCH(bool, accessible);
    QFETCH(QString, group);
    QFETCH(bool, inGroupNow);
    QFETCH(bool, groupListsUser);
    QFETCH(QStringList, mustContain);
    QFETCH(QStringList, mustNotContain);
    SerialPortAccess a;
    a.device = QStringLiteral("/dev/ttyUSB0");
    a.userName = QStringLiteral("alice");
    a.deviceGroup = group;
    a.accessible = accessible;
    a.inGroupNow = inGroupNow;
    a.groupListsUser = groupListsUser;
    const QString text = a.deniedText();
    for (const QString& part : mustContain)
        QVERIFY2(text.contains(part), qPrintable(text + " lacks " + part));
    for (const QString& part : mustNotContain)
        QVERIFY2(!text.contains(part), qPrintable(text + " has " + part));
    QVERIFY2(!text.contains('\n'), "one line");
}

void TestSerialPortAccess::probe_ownFileWithoutRights_notAccessibleButInGroup()
{
    if (geteuid() == 0)
        QSKIP("root may open any file: access cannot be denied to this process");
    QTemporaryFile file;
    QVERIFY(file.open());
    QVERIFY(::chmod(file.fileName().toLocal8Bit().constData(), 0) == 0);
    const SerialPortAccess a = SerialPortAccess::probe(file.fileName());
    QVERIFY(!a.accessible);
    QVERIFY(a.inGroupNow); // a new file gets the process's group
    QVERIFY(a.deniedText().contains("ls -l"));
}

void TestSerialPortAccess::probe_ownReadableFile_accessibleWithGroupName()
{
    QTemporaryFile file;
    QVERIFY(file.open());
    const SerialPortAccess a = SerialPortAccess::probe(file.fileName());
    QVERIFY(a.accessible);
    QVERIFY(a.inGroupNow);
    QCOMPARE(a.device, file.fileName());
    const group* gr = getgrgid(getegid());
    QVERIFY(gr);
    QCOMPARE(a.deviceGroup, QString::fromLocal8Bit(gr->gr_name));
    QVERIFY(!a.userName.isEmpty());
    QVERIFY(a.deniedText().contains("in use by another program"));
}

void TestSerialPortAccess::probe_missingDevice_groupUnknown_textNamesDialout()
{
    const SerialPortAccess a = SerialPortAccess::probe(QStringLiteral("/dev/stepdeck-no-such-tty"));
    QVERIFY(!a.accessible);
    QVERIFY(a.deviceGroup.isEmpty());
    QVERIFY(a.deniedText().contains("'dialout'"));
}

STEPDECK_TEST_GUILESS_MAIN(TestSerialPortAccess)
#include "tst_serialportaccess.moc"
