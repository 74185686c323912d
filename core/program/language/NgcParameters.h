#pragma once
#include "NgcExpression.h"
#include "program/ProgramCoordinates.h"
#include <QHash>
#include <array>
#include <vector>

namespace stepdeck::program {

// The parameters of a program in LinuxCNC's language (docs/programs.md "Parameters"):
// numbered #1..#5399, named local #<name> (per call) and global #<_name>.
// - #1..#30 are a call's arguments: saved at a call and given back at its return.
// - #31..#5060 are the program's; #5061..#5399 are LinuxCNC's reserved ones: read-only, and
//   either tied to what StepDeck knows before the run (#5220 the coordinate system, #5221..
//   #5350 G54..G59's offsets, #5210..#5219 G92's offset, none at the start, #5399 what the
//   last M66 read) or refused with the reason where only the run can know them (#5400.. the
//   tool, #5420.. the position, #5061.. probing).
// - Assignments are applied after their line (NgcInterpreter), as LinuxCNC does.
class NgcParameters : public NgcParameterSource
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::program::NgcParameters)
public:
    static constexpr int kLastNumbered = 5399;
    static constexpr int kLastWritable = 5060;
    static constexpr int kCallArguments = 30;

    NgcParameters(const CoordinateSystems& systems, int activeSystem);

    std::optional<double> numbered(int number, QString* why) const override;
    std::optional<double> named(const QString& name, QString* why) const override;
    bool exists(const QString& name) const override;

    // Empty: set; else why not.
    QString setNumbered(int number, double value);
    void setNamed(const QString& name, double value);

    // A call: #1..#30 become `arguments` (the rest 0) and named locals start empty.
    void enterCall(const QList<double>& arguments);
    void leaveCall();
    int callLevel() const { return int(m_frames.size()) - 1; }
    // What a return or endsub gives back (#<_value>, #<_value_returned>).
    void setReturned(std::optional<double> value);

    // What the program did that the reserved parameters follow.
    void noteSystem(int system) { m_system = system; }
    void noteOffsetsChanged(int line) { m_offsetsChangedAt = line; }
    void noteAxisOffsetChanged(int line) { m_axisOffsetChangedAt = line; }
    // An M66 on `line` that goes on only once its input reads `value` (NgcInterpreter).
    void noteInput(double value, int line)
    {
        m_input = value;
        m_inputLine = line;
    }

private:
    std::optional<double> reserved(int number, QString* why) const;

    CoordinateSystems m_systems;
    int m_system = 0;
    int m_offsetsChangedAt = 0;
    int m_axisOffsetChangedAt = 0;
    double m_input = 0;
    int m_inputLine = 0;
    std::vector<double> m_numbered;
    QHash<QString, double> m_globals;
    struct Frame
    {
        QHash<QString, double> locals;
        std::array<double, kCallArguments> saved{};
    };
    QList<Frame> m_frames;
};

} // namespace stepdeck::program
