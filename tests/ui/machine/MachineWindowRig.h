#pragma once
// The main window with a machine of two simulated controllers on pseudo-terminals (issue 19),
// shared by the machine window tests: an E-LAB X/Y/Z table (400, 400, 800 steps/mm) and a
// Nanotec drive 1 as the rotary axis A (100 steps/deg). One rig per test function: start() in
// init(), stop() in cleanup().
#include "../UiTestSupport.h"
#include "ModelBench.h"
#include "PtyDevice.h"
#include "machine/Machine.h"
#include "machine/MachineBar.h"
#include <QPushButton>
#include <QTemporaryDir>

namespace stepdeck::test {

struct MachineWindowRig
{
    std::unique_ptr<PtyDevice> elab;
    std::unique_ptr<PtyDevice> nanotec;
    std::unique_ptr<UiFixture> f;
    std::unique_ptr<QTemporaryDir> dir;

    // Fresh settings, both simulators, the window shown; false unless it became active.
    bool start()
    {
        QSettings().clear();
        elab = std::make_unique<PtyDevice>(QStringLiteral("elab"));
        nanotec = std::make_unique<PtyDevice>(QStringLiteral("nanotec"));
        dir = std::make_unique<QTemporaryDir>();
        f = std::make_unique<UiFixture>();
        window()->show();
        return QTest::qWaitForWindowActive(window());
    }

    void stop()
    {
        if (QGuiApplication::mouseButtons() & Qt::LeftButton)
            QTest::mouseRelease(window()->windowHandle(), Qt::LeftButton);
        f.reset(); // the window stops and closes every controller first
        elab.reset();
        nanotec.reset();
        dir.reset();
    }

    ui::MainWindow* window() const { return f->window.get(); }
    machine::Machine* machine() const { return window()->context()->machine(); }

    QString writeFile(const QByteArray& json,
                      const QString& name = QStringLiteral("test.machine.json")) const
    {
        const QString path = dir->filePath(name);
        QFile file(path);
        if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) ||
            file.write(json) != json.size())
            qFatal("cannot write %s", qPrintable(path));
        return path;
    }

    // The table with the rotary axis; xKeys and aKeys are appended to X's and A's entries
    // (", \"maxJogSpeed\": 2").
    QByteArray machineJson(const QString& name = QStringLiteral("Table with rotary axis"),
                           const QString& xKeys = {}, const QString& aKeys = {}) const
    {
        return QStringLiteral(R"({
  "format": "stepdeck-machine", "version": 1, "name": "%1",
  "controllers": [
    { "id": "table", "model": "elab", "port": "%2" },
    { "id": "rotary", "model": "nanotec", "port": "%3", "axes": { "X": 1 } }
  ],
  "axes": [
    { "name": "X", "controller": "table", "axis": "X", "unit": "mm", "stepsPerUnit": 400%4 },
    { "name": "Y", "controller": "table", "axis": "Y", "unit": "mm", "stepsPerUnit": 400 },
    { "name": "Z", "controller": "table", "axis": "Z", "unit": "mm", "stepsPerUnit": 800 },
    { "name": "A", "controller": "rotary", "axis": "X", "unit": "deg", "stepsPerUnit": 100%5 }
  ]
})")
            .arg(name, elab->path(), nanotec->path(), xKeys, aKeys)
            .toUtf8();
    }

    // Six axes on two in-process simulators: the table's X/Y/Z and a wrist's A/B/C.
    static QByteArray sixAxisJson()
    {
        return R"({
  "format": "stepdeck-machine", "version": 1, "name": "Six-axis cell with a long name",
  "controllers": [
    { "id": "table", "model": "elab", "port": "sim" },
    { "id": "wrist", "model": "nanotec", "port": "sim", "axes": { "X": 1, "Y": 2, "Z": 3 } }
  ],
  "axes": [
    { "name": "X", "controller": "table", "axis": "X", "unit": "mm", "stepsPerUnit": 400 },
    { "name": "Y", "controller": "table", "axis": "Y", "unit": "mm", "stepsPerUnit": 400 },
    { "name": "Z", "controller": "table", "axis": "Z", "unit": "mm", "stepsPerUnit": 800 },
    { "name": "A", "controller": "wrist", "axis": "X", "unit": "deg", "stepsPerUnit": 88.8889 },
    { "name": "B", "controller": "wrist", "axis": "Y", "unit": "deg", "stepsPerUnit": 100 },
    { "name": "C", "controller": "wrist", "axis": "Z", "unit": "steps" }
  ]
})";
    }

    // Opens the machine and connects every controller in `ids` with Connect all.
    bool openAndConnect(const QByteArray& json, const QStringList& ids) const
    {
        if (!window()->openMachine(writeFile(json)))
            return false;
        window()->machineBar()->connectButton()->click();
        for (const QString& id : ids) {
            ControllerSession* s = machine()->session(id);
            if (!s ||
                !QTest::qWaitFor([s] { return s->linkState() == LinkState::Connected; }, 10000))
                return false;
        }
        return true;
    }

    // The table with the rotary axis, connected, the board's setup written.
    bool openAndConnect(const QByteArray& json = {}) const
    {
        return openAndConnect(json.isEmpty() ? machineJson() : json,
                              {QStringLiteral("table"), QStringLiteral("rotary")}) &&
               writeElabSetup();
    }

    // The board moves only after its ramp setup was written (ModelInfo::setupBeforeMotion).
    bool writeElabSetup() const
    {
        ControllerSession* table = machine()->session(QStringLiteral("table"));
        QSignalSpy done(table, &ControllerSession::requestFinished);
        const RequestId id =
            table->writeParameters(setupBeforeMotionDefaults(*table->model()), false);
        return QTest::qWaitFor(
            [&] {
                return std::any_of(done.cbegin(), done.cend(), [id](const QList<QVariant>& args) {
                    const auto r = args.at(0).value<CommandResult>();
                    return r.id == id && r.ok();
                });
            },
            10000);
    }

    // The table's axes referenced by its own reference run, standing still.
    bool referenceTable() const
    {
        ControllerSession* table = machine()->session(QStringLiteral("table"));
        table->reference({{Axis::X, -1}, {Axis::Y, -1}, {Axis::Z, -1}});
        return QTest::qWaitFor(
            [table] {
                return table->status().axes.value(Axis::X).referenced &&
                       !table->status().anyMoving();
            },
            20000);
    }
};

} // namespace stepdeck::test
