// stepdeck: the operator and technician GUI.
//   stepdeck [--demo] [--simulate MODEL] [--model MODEL --port PORT] [--machine FILE]
//   [--poll-interval MS]
//   [--screenshot DIR] [--lang en|de]
#include "../cli/CliArguments.h"
#include "../common/SignalPipe.h"
#include "connection/ConnectionBar.h"
#include "machine/MachineControl.h"
#include "protocols/Registry.h"
#include "window/DemoMachine.h"
#include "window/HelpMenu.h"
#include "window/MainWindow.h"
#include "window/ScreenshotScript.h"
#include "window/Translations.h"
#include <QApplication>
#include <QCommandLineParser>
#include <QIcon>
#include <QLoggingCategory>
#include <QTextStream>
#include <QTimer>

using namespace stepdeck;

namespace {
Q_LOGGING_CATEGORY(lcGui, "stepdeck.gui")

// --help and --version are answered before QApplication connects to a display: they must work
// over ssh, in scripts and in a build chroot (the man page is generated from --help).
bool asksForTextOnly(int argc, char** argv)
{
    for (int i = 1; i < argc; ++i) {
        const QByteArrayView arg(argv[i]);
        if (arg == "--")
            break;
        if (arg == "-h" || arg == "-?" || arg == "--help" || arg == "--help-all" || arg == "-v" ||
            arg == "--version")
            return true;
    }
    return false;
}

// The window icon from resources/stepdeck.qrc; the installed desktop entry and the hicolor
// icons carry the same picture for menus and the task bar (resources/icons).
QIcon applicationIcon()
{
    QIcon icon;
    for (const int size : {16, 24, 32, 48, 64, 128, 256})
        icon.addFile(QStringLiteral(":/icons/stepdeck-%1.png").arg(size), QSize(size, size));
    return icon;
}
} // namespace

int main(int argc, char** argv)
{
    QApplication::setOrganizationName(QStringLiteral("StepDeck"));
    QApplication::setOrganizationDomain(QStringLiteral("stepdeck.invalid"));
    QApplication::setApplicationName(QStringLiteral("StepDeck"));
    QApplication::setApplicationVersion(QStringLiteral(STEPDECK_VERSION));
    // Wayland app id and X11 desktop-file hint: ties the windows to the menu entry's icon.
    QGuiApplication::setDesktopFileName(QStringLiteral("org.stepdeck.StepDeck"));

    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("StepDeck stepper-motor controller GUI"));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption simulate(
        QStringLiteral("simulate"), QStringLiteral("Connect to the in-process simulator of MODEL."),
        QStringLiteral("MODEL"));
    const QCommandLineOption model(QStringLiteral("model"), QStringLiteral("Controller model."),
                                   QStringLiteral("MODEL"));
    const QCommandLineOption port(QStringLiteral("port"),
                                  QStringLiteral("Port to connect at start: device path, "
                                                 "tcp://HOST:PORT or sim."),
                                  QStringLiteral("PORT"));
    const QCommandLineOption screenshot(
        QStringLiteral("screenshot"),
        QStringLiteral("Render every main page to DIR as PNG and exit (use with --simulate)."),
        QStringLiteral("DIR"));
    const QCommandLineOption lang(QStringLiteral("lang"),
                                  QStringLiteral("User interface language (en, de)."),
                                  QStringLiteral("CODE"));
    const QCommandLineOption pollInterval(QStringLiteral("poll-interval"),
                                          QStringLiteral("Status poll interval in milliseconds."),
                                          QStringLiteral("MS"));
    const QCommandLineOption machineFile(
        QStringLiteral("machine"),
        QStringLiteral("Open the machine described in FILE (docs/machines.md) and connect its "
                       "controllers."),
        QStringLiteral("FILE"));
    const QCommandLineOption demo(
        QStringLiteral("demo"),
        QStringLiteral("Open the built-in demo: a simulated plotting table in mm with a program "
                       "(what tools/run starts)."));
    parser.addOptions({simulate, model, port, machineFile, demo, screenshot, lang, pollInterval});
    if (asksForTextOnly(argc, argv)) {
        const QCoreApplication textOnly(argc, argv);
        parser.process(textOnly); // prints help or version (or the usage error) and exits
        return 0;
    }

    QApplication app(argc, argv);
    QApplication::setWindowIcon(applicationIcon());
    parser.process(app);

    // SIGTERM (logout, `kill`), SIGHUP and SIGINT end the program the way closing the window
    // does: the window's close path releases every jog and saves the layout, the event loop
    // ends with 0, and destroying the window closes the session (the model's stop, flushed,
    // then the port closed: ControllerSession::destroy). Installed before the window exists,
    // so SDL (which is told not to, see SdlGamepadDevice) never sees a default handler.
    const stepdeck::app::SignalPipe signalPipe([](int signalNumber) {
        qCInfo(lcGui) << "signal" << signalNumber << "received: closing";
        QApplication::closeAllWindows();
        QCoreApplication::quit();
    });

    ui::translations::install(&app, parser.isSet(lang) ? parser.value(lang)
                                                       : ui::translations::configured());

    QString modelId = parser.value(model);
    QString portSpec = parser.value(port);
    if (parser.isSet(simulate)) {
        modelId = parser.value(simulate);
        portSpec = QStringLiteral("sim");
    }
    if (!modelId.isEmpty() && !findModel(modelId)) {
        QTextStream(stderr) << QCoreApplication::translate("main", "unknown model '%1' (known: %2)")
                                   .arg(modelId, modelIds().join(QStringLiteral(", ")))
                            << "\n";
        return 2;
    }

    ui::MainWindow window;
    window.helpMenu()->setCommandLineHelp(cli::usageText());
    if (parser.isSet(pollInterval)) {
        bool ok = false;
        const int ms = parser.value(pollInterval).toInt(&ok, 10);
        if (!ok || !window.connectionBar()->setPollInterval(ms)) {
            QTextStream(stderr) << "--poll-interval needs milliseconds (10..2000)\n";
            return 2;
        }
    }
    if (!modelId.isEmpty())
        window.connectionBar()->setSelectedModel(modelId);
    if (parser.isSet(demo) && !parser.isSet(machineFile) && portSpec.isEmpty()) {
        QString error;
        if (!ui::DemoMachine::open(&window, &error))
            QTextStream(stderr) << error << "\n";
    } else if (parser.isSet(machineFile)) {
        // An invalid file is named in the window's message line (and here); nothing is opened.
        if (window.openMachine(parser.value(machineFile)))
            window.machineControl()->connect();
        else
            QTextStream(stderr) << window.lastError() << "\n";
    } else if (!portSpec.isEmpty()) {
        window.connectionBar()->setPortSpec(portSpec);
        window.connectionBar()->connectNow();
    }
    window.show();

    if (parser.isSet(screenshot)) {
        if (portSpec.isEmpty() && !parser.isSet(machineFile)) {
            QTextStream(stderr) << "--screenshot needs --simulate MODEL or --port PORT\n";
            return 2;
        }
        auto* script = new ui::ScreenshotScript(&window, parser.value(screenshot), &app);
        QObject::connect(script, &ui::ScreenshotScript::finished, &app,
                         [](int code) { QCoreApplication::exit(code); });
        QTimer::singleShot(0, script, &ui::ScreenshotScript::start);
    }
    return app.exec();
}
