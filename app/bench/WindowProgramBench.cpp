// stepdeck-bench --window-program (WindowProgramBench.h).
#include "WindowProgramBench.h"
#include "BenchDevice.h"
#include "BenchOutput.h"
#include "EventWait.h"
#include "machine/Machine.h"
#include "machine/MachineContext.h"
#include "machine/MachineDescription.h"
#include "program/ProgramControls.h"
#include "program/ProgramEditor.h"
#include "program/ProgramPage.h"
#include "program/ProgramPreviewView.h"
#include "program/ProgramRunner.h"
#include "protocols/Registry.h"
#include "window/MainWindow.h"
#include <QApplication>
#include <QElapsedTimer>
#include <QJsonDocument>
#include <QJsonObject>
#include <QPushButton>
#include <QSettings>
#include <QTabWidget>
#include <QTemporaryDir>
#include <cstdio>
#include <sys/resource.h>

namespace stepdeck::bench {

namespace {

// CPU seconds (user + system) of this thread (RUSAGE_THREAD) or the process (RUSAGE_SELF).
double cpuSeconds(int who)
{
    rusage usage{};
    getrusage(who, &usage);
    auto seconds = [](const timeval& t) { return double(t.tv_sec) + double(t.tv_usec) / 1e6; };
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

struct Figure
{
    double seconds = 0;        // wall clock measured
    double guiPercent = 0;     // GUI thread CPU, % of one core
    double processPercent = 0; // the whole process, % of one core
    qint64 blocks = 0;
    QString note;
};

QByteArray programText()
{
    // Short relative XY moves: every block ends at once, so the window has as many block
    // events to show per second as the wire allows.
    QByteArray text = "G91\n";
    for (int i = 1; i < kWindowProgramLines; ++i)
        text += i % 2 ? "G0 X10 Y5\n" : "G0 X-10 Y-5\n";
    return text;
}

BenchDevice::Config deviceConfig(const ModelInfo& model)
{
    BenchDevice::Config config;
    config.paced = true;
    config.prepare = [&model](Simulator* sim) {
        SimulatorScenario scenario;
        scenario.setupComplete = true; // the board moves without a setup written first
        QString ignored;
        if (model.scenario.apply && model.scenario.options.testFlag(ScenarioOption::SetupComplete))
            model.scenario.apply(scenario, sim, &ignored);
    };
    return config;
}

Figure measure(const ModelInfo& model, int seconds)
{
    Figure f;
    BenchDevice device(model, deviceConfig(model));
    if (!device.start(&f.note))
        return f;
    ui::MainWindow window;
    window.resize(1366, 768);
    window.show();
    ui::MachineContext* context = window.context();
    const machine::MachineDescription d =
        machine::MachineDescription::singleController(model, device.slavePath());
    if (!context->openMachine(d, &f.note))
        return f;
    context->connectMachine();
    machine::Machine* m = context->machine();
    if (!waitUntil([&] { return m->state() == machine::MachineState::Idle; }, 10000)) {
        f.note = QStringLiteral("the controller did not connect");
        return f;
    }
    ui::ProgramPage* page = window.programPage();
    window.raisePage(page);
    page->preview()->tabs()->setCurrentIndex(0); // the Path tab, the costly one
    page->editor()->setPlainText(QString::fromLatin1(programText()));
    page->checkNow();
    if (!waitUntil(
            [&] { return !page->isChecking() && page->controls()->runButton()->isEnabled(); },
            60000)) {
        f.note = QStringLiteral("the program was not checked clean");
        return f;
    }
    const double gui0 = cpuSeconds(RUSAGE_THREAD);
    const double process0 = cpuSeconds(RUSAGE_SELF);
    QElapsedTimer wall;
    wall.start();
    page->controls()->runButton()->click();
    program::ProgramRunner* runner = page->runner();
    // The check before the run goes off the GUI thread first (ProgramStarter).
    waitUntil([&] { return runner && !page->isStarting() && program::isEnded(runner->state()); },
              seconds * 1000);
    f.seconds = double(wall.nsecsElapsed()) / 1e9;
    f.guiPercent = 100.0 * (cpuSeconds(RUSAGE_THREAD) - gui0) / f.seconds;
    f.processPercent = 100.0 * (cpuSeconds(RUSAGE_SELF) - process0) / f.seconds;
    f.blocks = runner ? runner->blocksDone() : 0;
    if (runner && program::isEnded(runner->state()) &&
        runner->state() != program::RunState::Finished)
        f.note = runner->endMessage();
    if (runner && !program::isEnded(runner->state())) {
        runner->abort();
        waitUntil([&] { return program::isEnded(runner->state()); }, 10000);
    }
    context->closeMachine();
    return f;
}

} // namespace

int windowProgramBenchMain(int argc, char** argv)
{
    bool asked = false;
    for (int i = 1; i < argc; ++i)
        asked = asked || qstrcmp(argv[i], "--window-program") == 0;
    if (!asked)
        return -1;
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen"); // no window on anybody's desktop
    if (qEnvironmentVariableIsEmpty("QT_LOGGING_RULES"))
        qInstallMessageHandler(quiet);
    QApplication application(argc, argv);
    const QStringList args = application.arguments().mid(1);
    int seconds = 15;
    bool json = false;
    for (int i = 0; i < args.size(); ++i) {
        bool ok = true;
        if (args.at(i) == QLatin1String("--window-program")) {
            if (i + 1 < args.size() && !args.at(i + 1).startsWith(QLatin1String("--")))
                seconds = args.at(++i).toInt(&ok, 10);
        } else if (args.at(i) == QLatin1String("--json")) {
            json = true;
        } else {
            ok = false;
        }
        if (!ok || seconds < 1 || seconds > 3600) {
            print(stderr, QStringLiteral("stepdeck-bench: bad argument '%1'").arg(args.at(i)));
            return 2;
        }
    }
    // The window reads and writes the operator's settings: a settings file of its own.
    QTemporaryDir settings;
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settings.path());
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settings.path());
    const ModelInfo* model = findModel(QStringLiteral("elab"));
    if (!model) {
        print(stderr, QStringLiteral("stepdeck-bench: the E-LAB model is not built in"));
        return 1;
    }
    if (!json)
        print(stderr, QStringLiteral("measuring the window for %1 s while a %2-line program runs "
                                     "on %3 (platform %4) ...")
                          .arg(seconds)
                          .arg(kWindowProgramLines)
                          .arg(model->id, QGuiApplication::platformName()));
    const Figure f = measure(*model, seconds);
    if (json) {
        print(stdout,
              QString::fromUtf8(
                  QJsonDocument(
                      QJsonObject{{"windowProgram",
                                   QJsonObject{{"model", model->id},
                                               {"lines", kWindowProgramLines},
                                               {"platform", QGuiApplication::platformName()},
                                               {"seconds", f.seconds},
                                               {"guiThreadCpuPercent", f.guiPercent},
                                               {"processCpuPercent", f.processPercent},
                                               {"blocks", f.blocks},
                                               {"note", f.note}}}})
                      .toJson(QJsonDocument::Compact)));
    } else {
        print(stdout,
              QStringLiteral("  window while a program runs (%1, Path tab shown): GUI thread "
                             "%2 % of a core, whole process %3 % (controller and simulated "
                             "device included); %4 blocks in %5 s (%6 blocks/s)%7")
                  .arg(model->id)
                  .arg(f.guiPercent, 0, 'f', 1)
                  .arg(f.processPercent, 0, 'f', 1)
                  .arg(f.blocks)
                  .arg(f.seconds, 0, 'f', 1)
                  .arg(f.seconds > 0 ? double(f.blocks) / f.seconds : 0.0, 0, 'f', 1)
                  .arg(f.note.isEmpty() ? QString() : QStringLiteral("  ") + f.note));
    }
    return f.seconds > 0 ? 0 : 1;
}

} // namespace stepdeck::bench
