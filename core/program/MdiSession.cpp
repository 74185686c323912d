#include "MdiSession.h"
#include "ProgramParser.h"
#include <utility>

namespace stepdeck::program {

std::optional<Program> MdiSession::prepare(const QString& line, const QStringList& axisNames,
                                           QList<ProgramError>* errors)
{
    m_pending.reset();
    const QString text = line.trimmed();
    if (!text.isEmpty() && (m_history.isEmpty() || m_history.last() != text)) {
        m_history << text;
        if (m_history.size() > kHistoryLines)
            m_history.removeFirst();
    }
    QList<ProgramError> found;
    if (text.contains(QLatin1Char('\n')) || text.contains(QLatin1Char('\r'))) {
        found << ProgramError{1, 1, tr("an MDI line is one line")};
    } else {
        ProgramParser parser(axisNames, m_modal);
        parser.feed(text.toUtf8());
        std::optional<Program> program = parser.finish(&found);
        if (program && program->blockCount == 0)
            found << ProgramError{1, 1, tr("the line has nothing to run")};
        // Cutter compensation follows a path: a line alone has none to look ahead on.
        if (program && parser.state().modal.comp.on())
            found << ProgramError{1, 1,
                                  tr("cutter compensation (G41, G42) runs in programs, not "
                                     "in MDI")};
        if (found.isEmpty() && program) {
            program->source = ProgramSource::bytes(text.toUtf8());
            m_pending = parser.state().modal;
            return program;
        }
    }
    if (errors)
        *errors = found;
    return std::nullopt;
}

std::optional<int> MdiSession::lineRan(bool finished)
{
    std::optional<ModalState> after = std::exchange(m_pending, std::nullopt);
    if (!finished || !after)
        return std::nullopt;
    m_modal = *after;
    if (m_modal.coordinateSystem < 0)
        return std::nullopt;
    const int system = m_modal.coordinateSystem;
    m_modal.coordinateSystem = -1;
    return system;
}

void MdiSession::reset()
{
    m_modal = ModalState{};
    m_pending.reset();
}

QString MdiSession::modalText(const ModalState& modal)
{
    QStringList words;
    words << (modal.relative ? QStringLiteral("G91") : QStringLiteral("G90"))
          << (modal.inches ? QStringLiteral("G20") : QStringLiteral("G21"))
          << (modal.plane == Plane::XY   ? QStringLiteral("G17")
              : modal.plane == Plane::XZ ? QStringLiteral("G18")
                                         : QStringLiteral("G19"))
          << (modal.pathMode == PathMode::ExactPath   ? QStringLiteral("G61")
              : modal.pathMode == PathMode::ExactStop ? QStringLiteral("G61.1")
                                                      : QStringLiteral("G64"));
    if (modal.inverseTime)
        words << QStringLiteral("G93");
    if (modal.lengthTool >= 0)
        words << QStringLiteral("G43");
    if (modal.feed)
        words << QStringLiteral("F%1").arg(*modal.feed, 0, 'g', 8);
    return words.join(QLatin1Char(' '));
}

} // namespace stepdeck::program
