// Motion commands as LinuxCNC rs274-style canonical text (issue 49 item 6, docs/cli.md).
#include "CanonText.h"
#include "ProgramUnits.h"
#include <cmath>

namespace stepdeck::program {

using namespace stepdeck::motion;

namespace {

// Four decimals as rs274 prints them, without a negative zero.
QString number(double v)
{
    if (std::abs(v) < 0.00005)
        v = 0.0;
    return QString::number(v, 'f', 4);
}

// The plane's third axis (LinuxCNC's axis_end_point of ARC_FEED).
QString normalAxis(const QString& first, const QString& second)
{
    for (const QString& name : {QStringLiteral("X"), QStringLiteral("Y"), QStringLiteral("Z")})
        if (name != first && name != second)
            return name;
    return {};
}

} // namespace

CanonText::CanonText(const machine::MachineDescription& d) : m_d(d)
{
    m_frame.workOffset.assign(size_t(d.axes.size()), 0.0);
    m_frame.axisOffset.assign(size_t(d.axes.size()), 0.0);
}

QStringList CanonText::lines(const MotionCommand& command)
{
    const int line = lineOf(command);
    const QString n = line > 0 ? QStringLiteral("N%1").arg(line, 5, 10, QLatin1Char('0'))
                               : QStringLiteral("N.....");
    QStringList out;
    for (const QString& call : calls(command))
        out << QStringLiteral("%1 %2 %3").arg(++m_sequence, 5).arg(n, call);
    return out;
}

QStringList CanonText::calls(const MotionCommand& command)
{
    if (const auto* c = std::get_if<Traverse>(&command))
        return {QStringLiteral("STRAIGHT_TRAVERSE(%1)").arg(point(c->end))};
    if (const auto* c = std::get_if<StraightFeed>(&command))
        return {QStringLiteral("STRAIGHT_FEED(%1)").arg(point(c->end))};
    if (const auto* c = std::get_if<ArcFeed>(&command))
        return {arc(*c)};
    if (const auto* c = std::get_if<Dwell>(&command))
        return {QStringLiteral("DWELL(%1)").arg(number(c->seconds))};
    if (const auto* c = std::get_if<Reference>(&command)) {
        QStringList names;
        for (int i = 0; i < m_d.axes.size(); ++i)
            if (c->axes.isEmpty() || c->axes.contains(i))
                names << m_d.axes.at(i).name;
        return {QStringLiteral("REFERENCE_AXES(%1)").arg(names.join(QStringLiteral(", ")))};
    }
    if (const auto* c = std::get_if<SpindleOn>(&command))
        return {c->reverse ? QStringLiteral("START_SPINDLE_COUNTERCLOCKWISE(0)")
                           : QStringLiteral("START_SPINDLE_CLOCKWISE(0)")};
    if (std::holds_alternative<SpindleOff>(command))
        return {QStringLiteral("STOP_SPINDLE_TURNING(0)")};
    if (const auto* c = std::get_if<SpindleSpeed>(&command))
        return {QStringLiteral("SET_SPINDLE_SPEED(0, %1)").arg(number(c->rpm))};
    if (const auto* c = std::get_if<Coolant>(&command)) {
        switch (c->kind) {
        case Coolant::Kind::Mist:
            return {QStringLiteral("MIST_ON()")};
        case Coolant::Kind::Flood:
            return {QStringLiteral("FLOOD_ON()")};
        case Coolant::Kind::Off:
            return {QStringLiteral("MIST_OFF()"), QStringLiteral("FLOOD_OFF()")};
        }
    }
    if (const auto* c = std::get_if<Output>(&command))
        return {QStringLiteral("%1_AUX_OUTPUT_BIT(%2)")
                    .arg(c->on ? QStringLiteral("SET") : QStringLiteral("CLEAR"))
                    .arg(c->number)};
    if (const auto* c = std::get_if<WaitInput>(&command))
        return {QStringLiteral("WAIT(%1, 1, %2, %3)")
                    .arg(c->number)
                    .arg(c->high ? 3 : 4)
                    .arg(number(c->seconds))};
    if (const auto* c = std::get_if<Pause>(&command)) {
        switch (c->kind) {
        case Pause::Kind::Stop:
            return {QStringLiteral("PROGRAM_STOP()")};
        case Pause::Kind::OptionalStop:
            return {QStringLiteral("OPTIONAL_PROGRAM_STOP()")};
        case Pause::Kind::ToolChange:
            return {QStringLiteral("CHANGE_TOOL(%1)").arg(c->tool)};
        }
    }
    if (const auto* c = std::get_if<Message>(&command)) {
        QString text = c->text;
        text.replace(QLatin1Char('"'), QStringLiteral("\\\""));
        return {QStringLiteral("MESSAGE(\"%1\")").arg(text)};
    }
    if (std::holds_alternative<ProgramEnd>(command))
        return {QStringLiteral("PROGRAM_END()")};
    if (const auto* c = std::get_if<LengthUnits>(&command)) {
        m_inches = c->inches;
        return {QStringLiteral("USE_LENGTH_UNITS(%1)")
                    .arg(c->inches ? QStringLiteral("CANON_UNITS_INCHES")
                                   : QStringLiteral("CANON_UNITS_MM"))};
    }
    if (const auto* c = std::get_if<SelectPlane>(&command)) {
        static const char* const names[] = {"CANON_PLANE_XY", "CANON_PLANE_XZ", "CANON_PLANE_YZ"};
        return {QStringLiteral("SELECT_PLANE(%1)").arg(QLatin1String(names[int(c->plane)]))};
    }
    if (const auto* c = std::get_if<FeedRate>(&command)) {
        QStringList out;
        if (c->inverseTime != m_inverseTime) {
            m_inverseTime = c->inverseTime;
            out << QStringLiteral("SET_FEED_MODE(0, %1)").arg(c->inverseTime ? 1 : 0);
        }
        out << QStringLiteral("SET_FEED_RATE(%1)").arg(number(c->feed));
        return out;
    }
    if (const auto* c = std::get_if<Offsets>(&command))
        return offsets(*c);
    return {};
}

// Every axis in program terms, the machine's order.
QString CanonText::point(const MachinePoint& end) const
{
    QStringList values;
    for (int i = 0; i < m_d.axes.size(); ++i)
        values << programValue(i, size_t(i) < end.size() ? end[size_t(i)] : std::nullopt);
    return values.join(QStringLiteral(", "));
}

// ARC_FEED(first_end, second_end, first_axis, second_axis, rotation, axis_end_point, the other
// axes...): the plane's axes in LinuxCNC's order, the centre, the turns (+ counter-clockwise),
// the plane's third axis where the machine has it, then the rest in the machine's order.
QString CanonText::arc(const ArcFeed& a) const
{
    const auto end = [&](int i) {
        return programValue(i, size_t(i) < a.end.size() ? a.end[size_t(i)] : std::nullopt);
    };
    QStringList args;
    args << end(a.axes[0]) << end(a.axes[1]);
    for (int k = 0; k < 2; ++k)
        args << programValue(a.axes[k], a.centre[k]);
    args << QString::number(a.rotation);
    const int normal =
        m_d.axisIndex(normalAxis(m_d.axes.at(a.axes[0]).name, m_d.axes.at(a.axes[1]).name));
    if (normal >= 0)
        args << end(normal);
    for (int i = 0; i < m_d.axes.size(); ++i)
        if (i != a.axes[0] && i != a.axes[1] && i != normal)
            args << end(i);
    return QStringLiteral("ARC_FEED(%1)").arg(args.join(QStringLiteral(", ")));
}

// The parts of the frame that changed, as rs274's calls: SET_G5X_OFFSET(system 1..6, ...),
// SET_G92_OFFSET(...), USE_TOOL_LENGTH_OFFSET(...), every axis in program units.
QStringList CanonText::offsets(const Offsets& o)
{
    const auto lengths = [&](const std::vector<double>& values) {
        QStringList out;
        for (int i = 0; i < m_d.axes.size(); ++i)
            out << programLength(i, size_t(i) < values.size() ? values[size_t(i)] : 0.0);
        return out.join(QStringLiteral(", "));
    };
    QStringList out;
    if (o.system != m_frame.system || o.workOffset != m_frame.workOffset)
        out << QStringLiteral("SET_G5X_OFFSET(%1, %2)")
                   .arg(o.system + 1)
                   .arg(lengths(o.workOffset));
    if (o.axisOffset != m_frame.axisOffset)
        out << QStringLiteral("SET_G92_OFFSET(%1)").arg(lengths(o.axisOffset));
    if (o.tool != m_frame.tool || o.toolLength != m_frame.toolLength) {
        std::vector<double> tool(size_t(m_d.axes.size()), 0.0);
        if (o.toolAxis >= 0 && o.toolAxis < m_d.axes.size())
            tool[size_t(o.toolAxis)] = o.toolLength;
        out << QStringLiteral("USE_TOOL_LENGTH_OFFSET(%1)").arg(lengths(tool));
    }
    m_frame = o;
    return out;
}

double CanonText::perProgramUnit(int i) const
{
    return m_inches && m_d.axes.at(i).unit == machine::AxisUnit::Millimetre
               ? units::kMillimetresPerInch
               : 1.0;
}

QString CanonText::programLength(int i, double length) const
{
    return number(length / perProgramUnit(i));
}

QString CanonText::programValue(int i, std::optional<double> machine) const
{
    if (!machine)
        return QStringLiteral("?");
    double frame = 0;
    if (size_t(i) < m_frame.workOffset.size())
        frame += m_frame.workOffset[size_t(i)];
    if (size_t(i) < m_frame.axisOffset.size())
        frame += m_frame.axisOffset[size_t(i)];
    if (i == m_frame.toolAxis)
        frame += m_frame.toolLength;
    return number((*machine - frame) / perProgramUnit(i));
}

} // namespace stepdeck::program
