// ProgramSimulation: feed moves across controllers (issue 30). Each controller starts its part
// as soon as its link takes it, with no clock in common, so the path between the move's ends is
// approximate: the check estimates how far (the fastest axis' travel over the largest gap
// between its controllers' set-up times, Capabilities::moveSetupSeconds), the preview says it,
// and a machine file with "crossControllerFeed": false refuses such moves. The preview's note
// also says how each kind of controller follows F (docs/programs.md "How F maps onto each
// model").
#include "CoordinatedFeed.h"
#include "ProgramSimulation.h"
#include "ProgramUnits.h"
#include <algorithm>

namespace stepdeck::program {

// The error is told in the unit a path length is measured in (CoordinatedFeed::unitRank).
using CoordinatedFeed::unitRank;

void ProgramSimulation::noteControllers(const ProgramBlock& block, const AxisList& axes)
{
    // The controllers in the machine's order; the first axis of the machine's order names
    // the column.
    QStringList controllers;
    double earliest = 1e9, latest = 0;
    for (const machine::MachineController& c : m_facts.description.controllers) {
        const bool moves = std::any_of(axes.cbegin(), axes.cend(), [&](const auto& a) {
            return m_axes.at(a.first).controller == c.id;
        });
        if (!moves)
            continue;
        controllers << c.id;
        const double setup = m_facts.capabilities.value(c.id).moveSetupSeconds;
        earliest = std::min(earliest, setup);
        latest = std::max(latest, setup);
    }
    int first = axes.first().first;
    for (const auto& [a, speed] : axes) {
        Q_UNUSED(speed);
        first = std::min(first, a);
    }
    if (controllers.size() < 2)
        return;
    if (!m_facts.description.crossControllerFeed) {
        const int column = block.columnOf(m_axes.at(first).name);
        if (m_errors->once(block.line, column, kCrossController))
            m_errors->add(block.line, column, [&] {
                return ProgramCheck::tr("this feed move drives axes of controllers %1 together; "
                                        "the machine file forbids that "
                                        "(\"crossControllerFeed\": false), since their path "
                                        "between the ends is only approximate")
                    .arg(controllers.join(QStringLiteral(", ")));
            });
        return;
    }
    // At least a few ms apart even where both set up at once: each has its own thread and link.
    const double skew = std::max(latest - earliest, 0.005);
    const auto worst = std::min_element(axes.cbegin(), axes.cend(), [&](auto l, auto r) {
        const int rl = unitRank(m_axes.at(l.first).unit), rr = unitRank(m_axes.at(r.first).unit);
        return rl != rr ? rl < rr : l.second > r.second;
    });
    if (m_crossMoves++ == 0)
        m_crossLine = block.line;
    const machine::AxisUnit unit = m_axes.at(worst->first).unit;
    const double error = worst->second * skew;
    if (m_crossUnit.isEmpty() || unitRank(unit) < unitRank(*machine::unitFromKey(m_crossUnit)) ||
        (unitKey(unit) == m_crossUnit && error > m_crossError)) {
        m_crossError = error;
        m_crossUnit = machine::unitKey(unit);
    }
}

QString ProgramSimulation::controllersNote() const
{
    QStringList stream, coordinated, own; // controller ids by how they follow F
    for (auto c = m_facts.capabilities.cbegin(); c != m_facts.capabilities.cend(); ++c) {
        if (!c->feedRateParameter)
            continue;
        (c->contourStream ? stream : c->coordinatedFeed ? coordinated : own) << c.key();
    }
    const int kinds = int(!stream.isEmpty()) + int(!coordinated.isEmpty()) + int(!own.isEmpty());
    // On a machine of one kind the sentence says it all; else each names its controllers.
    const auto on = [kinds](const QStringList& ids, const QString& sentence) {
        return kinds > 1 ? ProgramCheck::tr("%1: %2").arg(ids.join(QStringLiteral(", ")), sentence)
                         : sentence;
    };
    QStringList parts;
    if (!coordinated.isEmpty())
        parts << on(coordinated, ProgramCheck::tr("each axis of a feed move runs at its share of "
                                                  "F, so the path is followed at F"));
    if (!stream.isEmpty())
        parts << on(stream, ProgramCheck::tr("contours (G64) run on the path at F as one step "
                                             "stream; a block of its own (G61) moves each axis "
                                             "at its own rate, starting together"));
    if (!own.isEmpty())
        parts << on(own, ProgramCheck::tr("the axes of a block start together, each at its own "
                                          "rate; the block ends when every axis has arrived"));
    if (m_crossMoves > 0)
        parts << ProgramCheck::tr("feed moves across controllers (%1 in all, the first on "
                                  "line %2) follow their path only approximately: up to about "
                                  "%3 %4 off")
                     .arg(m_crossMoves)
                     .arg(m_crossLine)
                     .arg(m_crossError, 0, 'f', 3)
                     .arg(m_crossUnit);
    return parts.join(QStringLiteral("; "));
}

} // namespace stepdeck::program
