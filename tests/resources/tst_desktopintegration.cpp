// resources/: the desktop entry and the AppStream metainfo pass the validators a Debian
// desktop and software centre use (desktop-file-validate, appstreamcli validate --no-net),
// and they agree with each other and with the installed icon and binary names.
#include "TestMain.h"
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QStandardPaths>
#include <QtTest>

namespace {
const QString kResources = QStringLiteral(STEPDECK_SOURCE_DIR "/resources");
const QString kAppId = QStringLiteral("org.stepdeck.StepDeck");

QString resource(const QString& name)
{
    return kResources + QLatin1Char('/') + name;
}
} // namespace

class TestDesktopIntegration : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void desktopEntry_passesDesktopFileValidate();
    void metainfo_passesAppstreamcliValidate();
    void desktopEntry_namesTheBinaryAndAnIconThatExists();
    void metainfo_launchesTheDesktopEntry_andItsScreenshotsExist();

private:
    void runValidator(const QString& tool, const QStringList& args);
};

void TestDesktopIntegration::runValidator(const QString& tool, const QStringList& args)
{
    const QString program = QStandardPaths::findExecutable(tool);
    if (program.isEmpty())
        QSKIP(qPrintable(tool + " not installed (tools/test installs desktop-file-utils and "
                                "appstream)"));
    QProcess process;
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(program, args);
    QVERIFY2(process.waitForFinished(60000), qPrintable(tool + " did not finish"));
    const QByteArray out = process.readAll();
    QVERIFY2(process.exitStatus() == QProcess::NormalExit && process.exitCode() == 0,
             qPrintable(tool + " failed:\n" + QString::fromUtf8(out)));
}

void TestDesktopIntegration::desktopEntry_passesDesktopFileValidate()
{
    runValidator(QStringLiteral("desktop-file-validate"), {resource(kAppId + ".desktop")});
}

void TestDesktopIntegration::metainfo_passesAppstreamcliValidate()
{
    runValidator(QStringLiteral("appstreamcli"),
                 {QStringLiteral("validate"), QStringLiteral("--no-net"),
                  resource(kAppId + ".metainfo.xml")});
}

void TestDesktopIntegration::desktopEntry_namesTheBinaryAndAnIconThatExists()
{
    QFile entry(resource(kAppId + ".desktop"));
    QVERIFY(entry.open(QIODevice::ReadOnly | QIODevice::Text));
    const QByteArray text = entry.readAll();
    QVERIFY(text.contains("\nExec=stepdeck\n"));
    QVERIFY(text.contains("\nIcon=" + kAppId.toUtf8() + "\n"));
    QVERIFY(QFile::exists(resource("icons/" + kAppId + ".svg")));
    for (const int size : {16, 24, 32, 48, 64, 128, 256}) {
        QVERIFY(QFile::exists(
            resource(QStringLiteral("icons/hicolor/%1x%1/apps/%2.png").arg(size).arg(kAppId))));
    }
}

void TestDesktopIntegration::metainfo_launchesTheDesktopEntry_andItsScreenshotsExist()
{
    QFile metainfo(resource(kAppId + ".metainfo.xml"));
    QVERIFY(metainfo.open(QIODevice::ReadOnly | QIODevice::Text));
    const QString text = QString::fromUtf8(metainfo.readAll());
    QVERIFY(text.contains("<id>" + kAppId + "</id>"));
    QVERIFY(text.contains("<launchable type=\"desktop-id\">" + kAppId + ".desktop</launchable>"));
    // Every screenshot the metainfo announces is one of docs/screenshots (same file name).
    const QRegularExpression image(QStringLiteral("<image>[^<]*/([^/<]+\\.png)</image>"));
    int count = 0;
    for (auto it = image.globalMatch(text); it.hasNext(); ++count) {
        const QString file = it.next().captured(1);
        QVERIFY2(QFile::exists(QStringLiteral(STEPDECK_SOURCE_DIR "/docs/screenshots/") + file),
                 qPrintable(file));
    }
    QVERIFY(count >= 1);
}

STEPDECK_TEST_GUILESS_MAIN(TestDesktopIntegration)
#include "tst_desktopintegration.moc"
