#pragma once
// The UI tests whose window must fit a 1366x768 laptop run on such a screen.
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QtTest>

namespace stepdeck::test {

// Runs `Test` on an offscreen screen of width x height (the window sizes its docks for the
// screen it starts on): the offscreen platform reads its screens from a file.
template <typename Test> int runOnScreen(int argc, char** argv, int width, int height)
{
    const QString config = QDir::temp().filePath(QStringLiteral("stepdeck-screen-%1x%2-%3.json")
                                                     .arg(width)
                                                     .arg(height)
                                                     .arg(QCoreApplication::applicationPid()));
    QFile file(config);
    if (!file.open(QIODevice::WriteOnly) ||
        file.write(QStringLiteral(R"({"screens": [{"name": "screen", "x": 0, "y": 0, "width": %1,
            "height": %2, "logicalDpi": 96, "logicalBaseDpi": 96, "dpr": 1}]})")
                       .arg(width)
                       .arg(height)
                       .toUtf8()) < 0)
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

// Runs `Test` on an offscreen 1366x768 laptop screen.
template <typename Test> int runOnLaptopScreen(int argc, char** argv)
{
    return runOnScreen<Test>(argc, argv, 1366, 768);
}

} // namespace stepdeck::test
