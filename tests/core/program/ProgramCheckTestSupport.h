#pragma once
// The machines the program check's tests run against (tst_programcheck, tst_programpreview),
// and small helpers to parse and print.
#include "ProgramParserTestSupport.h"
#include "program/ProgramCheck.h"
#include "program/ProgramParser.h"
#include "protocols/Registry.h"
#include <QtTest>

namespace stepdeck::program::checktest {

using machine::AxisUnit;
using machine::MachineAxis;
using machine::MachineController;
using machine::MachineDescription;

// What `--setup-defaults` writes (ModelInfo::setupBeforeMotion at the schema's defaults): what a
// session knows its device holds once the setup was written.
inline ParameterSet setupDefaults(const ModelInfo& info)
{
    ParameterSet set;
    for (const QString& name : info.setupBeforeMotion)
        if (const ParameterSpec* spec = info.schema.find(name)) {
            ParameterValue v;
            if (spec->perAxis)
                for (Axis a : info.capabilities.axes)
                    v.perAxis.insert(a, spec->defaultValue);
            else
                v.global = spec->defaultValue;
            set.insert(name, v);
        }
    return set;
}

// The machines' E-LAB tables are set up for contours (issue 30): start speed 2401 steps/s on
// every axis, so a stream ticks at the wire's 2100/s (motion::StreamExecutor::tickRate).
inline void addController(MachineFacts* facts, const QString& id, const QString& model)
{
    const ModelInfo* info = findModel(model);
    QVERIFY2(info, qPrintable(model));
    MachineController c;
    c.id = id;
    c.modelId = model;
    c.port = QStringLiteral("sim");
    facts->description.controllers << c;
    facts->capabilities.insert(id, info->capabilities);
    facts->schemas.insert(id, info->schema);
    if (model == QLatin1String("elab")) {
        ParameterValue start;
        for (Axis a : info->capabilities.axes)
            start.perAxis.insert(a, 2401);
        facts->knownParameters[id].insert(QStringLiteral("start-speed"), start);
    }
}

inline MachineAxis axis(const QString& name, const QString& controller, Axis on, AxisUnit unit,
                        double stepsPerUnit, double min, double max)
{
    MachineAxis a;
    a.name = name;
    a.controller = controller;
    a.axis = on;
    a.unit = unit;
    a.stepsPerUnit = stepsPerUnit;
    a.softMinimum = min;
    a.softMaximum = max;
    return a;
}

// The machines of the tests, by name:
// "mill": E-LAB "table" X Y Z (mm), laser axes "tilt" A (deg);
// "io": E-LAB "table" X, EMIS "io1" U and "io2" V (7 outputs and 8 inputs each);
// "mixed": E-LAB "table" X (mm), Nanotec "rotary" A (deg);
// "noReference": the mill whose "tilt" has no reference run;
// "emis", "nanotec": one controller in its steps (MachineDescription::singleController);
// "emisKnown": the EMIS whose adapter knows its work speed (written in this session);
// "emisKnownX": the same for X only.
// Any of them with "Refuse" appended ("millRefuse"): the machine file's "limits": "refuse"
// (issue 50), a feed or S above the machine's highest refused as before instead of run at it.
inline MachineFacts machineFacts(const QString& name)
{
    if (name.endsWith(QLatin1String("Refuse"))) {
        MachineFacts f = machineFacts(name.chopped(6));
        f.description.limits = machine::LimitPolicy::Refuse;
        return f;
    }
    MachineFacts f;
    if (name == QLatin1String("emisKnown") || name == QLatin1String("emisKnownX")) {
        f = machineFacts(QStringLiteral("emis"));
        ParameterValue work;
        for (Axis a : {Axis::X, Axis::Y, Axis::Z, Axis::U})
            if (a == Axis::X || name == QLatin1String("emisKnown"))
                work.perAxis.insert(a, 4000);
        f.knownParameters[QStringLiteral("emis")].insert(QStringLiteral("work-speed"), work);
        return f;
    }
    if (name == QLatin1String("emis") || name == QLatin1String("nanotec")) {
        const ModelInfo* info = findModel(name);
        f.description = MachineDescription::singleController(*info, QStringLiteral("sim"));
        f.capabilities.insert(name, info->capabilities);
        f.schemas.insert(name, info->schema);
        return f;
    }
    if (name == QLatin1String("mixed")) {
        addController(&f, "table", "elab");
        addController(&f, "rotary", "nanotec");
        f.description.axes << axis("X", "table", Axis::X, AxisUnit::Millimetre, 100, 0, 100)
                           << axis("A", "rotary", Axis::X, AxisUnit::Degree, 100, -360, 360);
        return f;
    }
    if (name == QLatin1String("io")) {
        addController(&f, "table", "elab");
        addController(&f, "io1", "emis");
        addController(&f, "io2", "emis");
        f.description.axes << axis("X", "table", Axis::X, AxisUnit::Millimetre, 100, 0, 100)
                           << axis("U", "io1", Axis::X, AxisUnit::Step, 1, -1e6, 1e6)
                           << axis("V", "io2", Axis::X, AxisUnit::Step, 1, -1e6, 1e6);
        return f;
    }
    addController(&f, "table", "elab");
    addController(&f, "tilt", "laser-axis");
    MachineAxis x = axis("X", "table", Axis::X, AxisUnit::Millimetre, 100, 0, 100);
    x.maxJogSpeed = 50; // mm/s; Y and Z go at the E-LAB's 5000 steps/s
    f.description.axes << x << axis("Y", "table", Axis::Y, AxisUnit::Millimetre, 200, 0, 200)
                       << axis("Z", "table", Axis::Z, AxisUnit::Millimetre, 100, -50, 0)
                       << axis("A", "tilt", Axis::X, AxisUnit::Degree, 10, -90, 90);
    if (name == QLatin1String("noReference"))
        f.capabilities["tilt"].motionModes.removeAll(MotionMode::Reference);
    return f;
}

// "X=0 Y=5": the known positions.
inline QMap<QString, double> positions(const QString& text)
{
    QMap<QString, double> out;
    for (const QString& pair : text.split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
        const QStringList kv = pair.split(QLatin1Char('='));
        out.insert(kv.at(0), kv.at(1).toDouble());
    }
    return out;
}

inline Program parsed(const QString& text, const MachineFacts& facts)
{
    QStringList names;
    for (const MachineAxis& a : facts.description.axes)
        names << a.name;
    QList<ProgramError> errors;
    const std::optional<Program> p = ProgramParser::parse(text.toUtf8(), names, &errors);
    if (!p) {
        for (const ProgramError& e : errors)
            qWarning() << e.text();
        return {};
    }
    return *p;
}

// One function for both helpers' users: a file of a test batch may see both namespaces.
using parsertest::texts;

} // namespace stepdeck::program::checktest
