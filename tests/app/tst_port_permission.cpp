// A serial port the user may not open: stepdeck-cli (and through the same core text the GUI)
// names the group that owns the device and how to join it, instead of a bare Qt error.
// The device is a pseudo-terminal given the rights of a Debian serial port (root:dialout 0660);
// as root the CLI is run as `nobody` (setpriv), otherwise the pty's rights are taken away.
#include "ProcessSupport.h"
#include "TestMain.h"
#include "sim/PtyEndpoint.h"
#include <QStandardPaths>
#include <QtTest>
#include <grp.h>
#include <sys/stat.h>
#include <unistd.h>

using namespace stepdeck;

class TestPortPermission : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void cli_portOfAnotherGroup_namesGroupAndHowToJoin();
    void cli_portWithoutRights_asMember_namesPermissions();
};

namespace {
QString cliPath()
{
    return qEnvironmentVariable("STEPDECK_BIN_DIR") + QStringLiteral("/stepdeck-cli");
}
} // namespace

void TestPortPermission::cli_portOfAnotherGroup_namesGroupAndHowToJoin()
{
    const QString setpriv = QStandardPaths::findExecutable(QStringLiteral("setpriv"));
    if (geteuid() != 0 || setpriv.isEmpty())
        QSKIP("needs root and setpriv to run the CLI as a user outside the device's group");
    const group* dialout = getgrnam("dialout");
    if (!dialout)
        QSKIP("no group dialout on this system");
    PtyEndpoint device;
    QString error;
    QVERIFY2(device.create(&error), qPrintable(error));
    const QByteArray path = device.slavePath().toLocal8Bit();
    QVERIFY(::chown(path.constData(), 0, dialout->gr_gid) == 0);
    QVERIFY(::chmod(path.constData(), 0660) == 0);

    const auto run =
        testing::runProcess(setpriv,
                            {"--reuid=65534", "--regid=65534", "--clear-groups", cliPath(),
                             "--model", "elab", "--port", device.slavePath(), "status"},
                            30000);
    QCOMPARE(run.exitCode, 6); // link down: could not connect
    const QString err = QString::fromLocal8Bit(run.err);
    QVERIFY2(err.contains(device.slavePath()), qPrintable(err));
    QVERIFY2(err.contains("access denied"), qPrintable(err));
    QVERIFY2(err.contains("'dialout'"), qPrintable(err));
    QVERIFY2(err.contains("sudo adduser nobody dialout"), qPrintable(err));
}

void TestPortPermission::cli_portWithoutRights_asMember_namesPermissions()
{
    if (geteuid() == 0)
        QSKIP("root opens any device: its rights cannot be taken away from this process");
    PtyEndpoint device;
    QString error;
    QVERIFY2(device.create(&error), qPrintable(error));
    QVERIFY(::chmod(device.slavePath().toLocal8Bit().constData(), 0) == 0);
    const auto run = testing::runProcess(
        cliPath(), {"--model", "elab", "--port", device.slavePath(), "status"}, 30000);
    QCOMPARE(run.exitCode, 6);
    const QString err = QString::fromLocal8Bit(run.err);
    QVERIFY2(err.contains("access denied"), qPrintable(err));
    QVERIFY2(err.contains("ls -l " + device.slavePath()), qPrintable(err));
}

STEPDECK_TEST_GUILESS_MAIN(TestPortPermission)
#include "tst_port_permission.moc"
