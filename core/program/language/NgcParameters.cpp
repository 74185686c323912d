#include "NgcParameters.h"

namespace stepdeck::program {

NgcParameters::NgcParameters(const CoordinateSystems& systems, int activeSystem)
    : m_systems(systems), m_system(activeSystem), m_numbered(size_t(kLastNumbered) + 1, 0.0)
{
    m_frames.push_back(Frame{}); // the main program's named locals
}

std::optional<double> NgcParameters::numbered(int number, QString* why) const
{
    if (number >= 1 && number <= kLastWritable)
        return m_numbered[size_t(number)];
    return reserved(number, why);
}

// LinuxCNC's reserved parameters (its manual, "Numbered Parameters"), as far as StepDeck can
// know them before the run.
std::optional<double> NgcParameters::reserved(int n, QString* why) const
{
    auto refuse = [why](const QString& text) -> std::optional<double> {
        *why = text;
        return std::nullopt;
    };
    if (n >= 5061 && n <= 5070)
        return refuse(tr("#%1 holds a probing result (G38), which StepDeck does not run").arg(n));
    if ((n >= 5161 && n <= 5169) || (n >= 5181 && n <= 5189))
        return refuse(tr("#%1 is LinuxCNC's stored G28/G30 position; StepDeck's G28 is the "
                         "reference run and keeps none")
                          .arg(n));
    if (n >= 5210 && n <= 5219) {
        if (m_axisOffsetChangedAt > 0)
            return refuse(tr("#%1 is G92's offset, which line %2 set from where the axes "
                             "stand: only the run knows it")
                              .arg(n)
                              .arg(m_axisOffsetChangedAt));
        return 0.0; // no G92 offset at the start: it holds for one run only
    }
    if (n == 5220)
        return double(m_system + 1);
    if (n >= 5221 && n <= 5390) {
        const int system = (n - 5221) / 20;
        const int axis = (n - 5221) % 20;
        if (system >= kCoordinateSystems || axis > 9)
            return refuse(
                tr("#%1: StepDeck has the coordinate systems G54..G59 (#5221..#5330)").arg(n));
        if (m_offsetsChangedAt > 0)
            return refuse(tr("#%1 is an offset that line %2 changed (G10): only the run knows "
                             "it")
                              .arg(n)
                              .arg(m_offsetsChangedAt));
        if (axis == 9)
            return 0.0; // R, the rotation: none (G10's R is refused)
        const QString letter = QString(QLatin1Char("XYZABCUVW"[axis]));
        return m_systems[size_t(system)].value(letter, 0.0);
    }
    if (n == 5399) {
        if (m_inputLine > 0)
            return m_input;
        return refuse(tr("#5399 holds what M66 read, and no M66 has run before this line"));
    }
    if (n >= 5400 && n <= 5413)
        return refuse(tr("#%1 is the loaded tool's, known only at run time").arg(n));
    if (n >= 5420 && n <= 5428)
        return refuse(tr("#%1 is the current position, known only at run time").arg(n));
    if (n > kLastWritable && n <= kLastNumbered)
        return 0.0; // reserved by LinuxCNC for nothing StepDeck has: read as 0
    return refuse(
        tr("#%1 is not a parameter: numbered parameters are #1..#%2").arg(n).arg(kLastNumbered));
}

std::optional<double> NgcParameters::named(const QString& name, QString* why) const
{
    if (name.startsWith(QLatin1Char('_'))) {
        const auto it = m_globals.find(name);
        if (it != m_globals.end())
            return *it;
        if (name == QLatin1String("_call_level"))
            return double(callLevel());
        *why = tr("#<%1> is not set (LinuxCNC's predefined values of the machine's state are "
                  "known only at run time, and StepDeck works a program out before it runs)")
                   .arg(name);
        return std::nullopt;
    }
    const auto it = m_frames.last().locals.find(name);
    if (it != m_frames.last().locals.end())
        return *it;
    *why = tr("#<%1> is not set here (a name without \"_\" is local to its subroutine)").arg(name);
    return std::nullopt;
}

bool NgcParameters::exists(const QString& name) const
{
    if (name.startsWith(QLatin1Char('_')))
        return m_globals.contains(name) || name == QLatin1String("_call_level");
    return m_frames.last().locals.contains(name);
}

QString NgcParameters::setNumbered(int number, double value)
{
    if (number >= 1 && number <= kLastWritable) {
        m_numbered[size_t(number)] = value;
        return {};
    }
    if (number >= 5221 && number <= 5390)
        return tr("#%1 is a coordinate system's offset, read-only here: set it with G10 L2 or "
                  "at the position display")
            .arg(number);
    if (number <= kLastNumbered || (number >= 5400 && number <= 5428))
        return tr("#%1 is reserved by LinuxCNC and read-only").arg(number);
    return tr("#%1 is not a parameter: numbered parameters are #1..#%2")
        .arg(number)
        .arg(kLastNumbered);
}

void NgcParameters::setNamed(const QString& name, double value)
{
    if (name.startsWith(QLatin1Char('_')))
        m_globals.insert(name, value);
    else
        m_frames.last().locals.insert(name, value);
}

void NgcParameters::enterCall(const QList<double>& arguments)
{
    Frame frame;
    for (int i = 0; i < kCallArguments; ++i) {
        frame.saved[size_t(i)] = m_numbered[size_t(i) + 1];
        m_numbered[size_t(i) + 1] = i < arguments.size() ? arguments.at(i) : 0.0;
    }
    m_frames.push_back(std::move(frame));
}

void NgcParameters::leaveCall()
{
    if (m_frames.size() <= 1)
        return;
    const Frame frame = m_frames.takeLast();
    for (int i = 0; i < kCallArguments; ++i)
        m_numbered[size_t(i) + 1] = frame.saved[size_t(i)];
}

void NgcParameters::setReturned(std::optional<double> value)
{
    m_globals.insert(QStringLiteral("_value_returned"), value ? 1.0 : 0.0);
    m_globals.insert(QStringLiteral("_value"), value.value_or(0.0));
}

} // namespace stepdeck::program
