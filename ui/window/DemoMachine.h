#pragma once
#include <QCoreApplication>
#include <QString>

namespace stepdeck::ui {

class MainWindow;

// The built-in demo (issue 31, "What a newcomer sees first"; `stepdeck --demo`, which tools/run
// starts): a plotting table on the in-process E-LAB simulator, in mm (X 0..150, Y 0..100,
// Z 0..40, 200 steps/mm on X and Y, 400 on Z), its setup written on connect (a start speed
// of 1000 steps/s, so that contours run at up to about F300), and a demo program open: a
// rounded frame and a circle. Reference all, then Run: the whole path runs in under two
// minutes. The files are ordinary ones in the application's data folder ("demo"), written
// when missing, so that a newcomer can look at them, change them and open them again.
class DemoMachine
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::ui::DemoMachine)
public:
    static QString directory();
    static QString machinePath();
    static QString programPath();
    // Writes what is missing of the demo's files, opens the machine, connects it and opens the
    // program; false with *error (a folder that cannot be written, a file that does not open).
    static bool open(MainWindow* window, QString* error);

private:
    static bool writeIfMissing(const QString& path, const QByteArray& content, QString* error);
};

} // namespace stepdeck::ui
