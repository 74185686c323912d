#pragma once
// The UI tests whose window must fit a 1366x768 laptop run on such a screen.
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QtTest>

namespace stepdeck::test {

// Runs `Test` on an offscreen 1366x768 laptop screen (the window sizes its docks for the
// screen it starts on): the offscreen platform reads its screens from a file.
template <typename Test> int runOnLaptopScreen(int argc, char** argv)
{
    const QString config = QDir::temp().filePath(
        QStringLiteral("stepdeck-screen-1366x768-%1.json").arg(QCoreApplication::applicationPid()));
    QFile file(config);
    if (!file.open(QIODevice::WriteOnly) ||
        file.write(R"({"screens": [{"name": "laptop", "x": 0, "y": 0, "width": 1366,
            "height": 768, "logicalDpi": 96, "logicalBaseDpi": 96, "dpr": 1}]})") < 0)
        return 2;
    file.close();
    qputenv("QT_QPA_PLATFORM", "offscreen:configfile=" + config.toLocal8Bit());
    int result = 0;
    {
        QApplication app(argc, argv);
        Test test;
        result = QTest::qExec(&test, argc, argv);
    }
    QFile::remove(config);
    return result;
}

} // namespace stepdeck::test
