// stepdeck-bench --preview-frame (PreviewFrameBench.h).
#include "PreviewFrameBench.h"
#include "BenchOutput.h"
#include "Measurements.h"
#include "machine/MachineDescription.h"
#include "program/ProgramPathView.h"
#include <QApplication>
#include <QElapsedTimer>
#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMouseEvent>
#include <QPainter>
#include <QSettings>
#include <QTemporaryDir>
#include <QWheelEvent>
#include <cmath>
#include <functional>

namespace stepdeck::bench {

using ui::PreviewViewKind;
using ui::ProgramPathView;

namespace {

constexpr QSize kViewSize(800, 600);

machine::MachineDescription benchMachine()
{
    machine::MachineDescription d;
    const QList<std::pair<QString, std::pair<double, double>>> axes{
        {QStringLiteral("X"), {0, 300}},
        {QStringLiteral("Y"), {0, 200}},
        {QStringLiteral("Z"), {-40, 0}}};
    for (const auto& [name, limits] : axes) {
        machine::MachineAxis axis;
        axis.name = name;
        axis.controller = QStringLiteral("c1");
        axis.unit = machine::AxisUnit::Millimetre;
        axis.softMinimum = limits.first;
        axis.softMaximum = limits.second;
        d.axes << axis;
    }
    return d;
}

// A pocket of circles as a CAM post writes them, each drawn as 0.01 mm chords: at every depth
// rings of growing radius about several centres, a rapid up, over and down between them, until
// the preview's path is full.
program::ProgramPreview benchPreview()
{
    program::ProgramPreview preview;
    auto add = [&](double x, double y, double z, bool rapid) {
        program::PreviewPoint p;
        p.line = int(preview.path.size()) + 1;
        p.position = {{QStringLiteral("X"), x}, {QStringLiteral("Y"), y}, {QStringLiteral("Z"), z}};
        p.rapid = rapid;
        preview.path << p;
    };
    const int maxPoints = program::ProgramPreview::kMaxPathPoints;
    for (int pocket = 0; preview.path.size() < maxPoints; ++pocket) {
        const double cx = 40 + (pocket % 5) * 50, cy = 40 + (pocket / 5 % 3) * 50;
        for (int depth = 1; depth <= 4 && preview.path.size() < maxPoints; ++depth) {
            const double z = -2.0 * depth;
            add(cx + 2, cy, 5, true);
            add(cx + 2, cy, z, false);
            for (double r = 2; r <= 20 && preview.path.size() < maxPoints; r += 2) {
                // Chords within 0.01 mm: angle step 2 acos(1 - tol / r).
                const double step = 2 * std::acos(1 - 0.01 / r);
                const int chords = int(std::ceil(2 * M_PI / step));
                for (int i = 1; i <= chords && preview.path.size() < maxPoints; ++i)
                    add(cx + r * std::cos(2 * M_PI * i / chords),
                        cy + r * std::sin(2 * M_PI * i / chords), z, false);
            }
            add(cx, cy, 5, true);
        }
    }
    preview.path.resize(maxPoints);
    return preview;
}

struct FrameFigures
{
    double medianMs = 0, p99Ms = 0;
    double markerMedianMs = 0; // only the tool marker moved: the cached path is reused
    int frames = 0;
};

double timedFrame(ProgramPathView& view, QImage& image, const std::function<void()>& input)
{
    QElapsedTimer timer;
    timer.start();
    input();
    image.fill(Qt::white);
    view.render(&image);
    return double(timer.nsecsElapsed()) / 1e6;
}

FrameFigures measure(ProgramPathView& view, PreviewViewKind kind, int frames)
{
    view.chooseView(kind);
    QImage image(kViewSize, QImage::Format_ARGB32_Premultiplied);
    view.render(&image); // the projection built, the first picture drawn
    QList<double> times, markerTimes;
    QPointF dragAt(400, 300);
    for (int i = 0; i < frames; ++i) {
        // Alternately a wheel notch (in, then out again, at moving cursor positions) and a
        // drag step, as an operator does.
        const QPointF cursor(200 + (i * 37) % 400, 150 + (i * 53) % 300);
        times << timedFrame(view, image, [&] {
            if (i % 2 == 0) {
                QWheelEvent wheel(cursor, cursor, QPoint(), QPoint(0, i % 4 == 0 ? 120 : -120),
                                  Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
                QApplication::sendEvent(&view, &wheel);
            } else {
                const QPointF to = dragAt + QPointF(i % 3 == 0 ? 6 : -6, i % 5 == 0 ? 4 : -4);
                // A pan (Shift+left: a plain left drag orbits since issue 47).
                QMouseEvent press(QEvent::MouseButtonPress, dragAt, dragAt, Qt::LeftButton,
                                  Qt::LeftButton, Qt::ShiftModifier);
                QMouseEvent move(QEvent::MouseMove, to, to, Qt::NoButton, Qt::LeftButton,
                                 Qt::ShiftModifier);
                QMouseEvent release(QEvent::MouseButtonRelease, to, to, Qt::LeftButton,
                                    Qt::NoButton, Qt::ShiftModifier);
                QApplication::sendEvent(&view, &press);
                QApplication::sendEvent(&view, &move);
                QApplication::sendEvent(&view, &release);
            }
        });
        markerTimes << timedFrame(view, image, [&] {
            view.setCurrent({{QStringLiteral("X"), 40.0 + i % 20},
                             {QStringLiteral("Y"), 40.0},
                             {QStringLiteral("Z"), -2.0}});
        });
    }
    FrameFigures f;
    f.frames = frames;
    f.medianMs = median(times);
    f.p99Ms = percentile(times, 0.99);
    f.markerMedianMs = median(markerTimes);
    return f;
}

QJsonObject toJson(const FrameFigures& f)
{
    return QJsonObject{{"medianMs", f.medianMs},
                       {"p99Ms", f.p99Ms},
                       {"markerMedianMs", f.markerMedianMs},
                       {"frames", f.frames}};
}

// "--preview-frame [FRAMES] [--json]"; false (said on stderr) for anything else.
bool parseArguments(const QStringList& args, int* frames, bool* json)
{
    for (int i = 0; i < args.size(); ++i) {
        bool ok = true;
        if (args.at(i) == QLatin1String("--preview-frame")) {
            if (i + 1 < args.size() && !args.at(i + 1).startsWith(QLatin1String("--")))
                *frames = args.at(++i).toInt(&ok, 10);
        } else if (args.at(i) == QLatin1String("--json")) {
            *json = true;
        } else {
            ok = false;
        }
        if (!ok || *frames < 1 || *frames > 100000) {
            print(stderr, QStringLiteral("stepdeck-bench: bad argument '%1'").arg(args.at(i)));
            return false;
        }
    }
    return true;
}

} // namespace

int previewFrameBenchMain(int argc, char** argv)
{
    bool asked = false;
    for (int i = 1; i < argc; ++i)
        asked = asked || qstrcmp(argv[i], "--preview-frame") == 0;
    if (!asked)
        return -1;
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen"); // no window on anybody's desktop
    QApplication application(argc, argv);
    int frames = 300;
    bool json = false;
    if (!parseArguments(application.arguments().mid(1), &frames, &json))
        return 2;
    // The view remembers its view in the settings: a settings file of its own.
    QTemporaryDir settings;
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settings.path());
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settings.path());
    const program::ProgramPreview preview = benchPreview();
    ProgramPathView view;
    view.resize(kViewSize);
    QElapsedTimer load;
    load.start();
    view.setPreview(preview, benchMachine());
    QImage image(kViewSize, QImage::Format_ARGB32_Premultiplied);
    view.render(&image);
    const double loadMs = double(load.nsecsElapsed()) / 1e6;
    if (!json)
        print(stderr, QStringLiteral("measuring %1 pan/zoom frames per view of a %2-point path "
                                     "at %3x%4 (platform %5) ...")
                          .arg(frames)
                          .arg(preview.path.size())
                          .arg(kViewSize.width())
                          .arg(kViewSize.height())
                          .arg(QGuiApplication::platformName()));
    const FrameFigures top = measure(view, PreviewViewKind::Top, frames);
    const FrameFigures iso = measure(view, PreviewViewKind::Isometric, frames);
    if (json) {
        const QJsonObject out{
            {"previewFrame", QJsonObject{{"points", int(preview.path.size())},
                                         {"width", kViewSize.width()},
                                         {"height", kViewSize.height()},
                                         {"platform", QGuiApplication::platformName()},
                                         {"loadMs", loadMs},
                                         {"top", toJson(top)},
                                         {"isometric", toJson(iso)}}}};
        print(stdout, QString::fromUtf8(QJsonDocument(out).toJson(QJsonDocument::Indented)));
        return 0;
    }
    print(stdout, QStringLiteral("preview of %1 points: set and first drawn in %2 ms")
                      .arg(preview.path.size())
                      .arg(loadMs, 0, 'f', 1));
    for (const auto& [name, f] :
         {std::pair{QStringLiteral("top"), top}, std::pair{QStringLiteral("isometric"), iso}})
        print(stdout, QStringLiteral("%1: pan/zoom frame median %2 ms, p99 %3 ms; marker-only "
                                     "frame median %4 ms (%5 frames)")
                          .arg(name)
                          .arg(f.medianMs, 0, 'f', 2)
                          .arg(f.p99Ms, 0, 'f', 2)
                          .arg(f.markerMedianMs, 0, 'f', 2)
                          .arg(f.frames));
    return 0;
}

} // namespace stepdeck::bench
