#pragma once
// The toolpath view's margin and legend rows: ProgramPathView.cpp reserves the room that
// ProgramPathViewPaint.cpp draws in, so both take the figures from here.

namespace stepdeck::ui::pathviewlayout {

constexpr int kMargin = 12;
constexpr int kLegendPadding = 4;
constexpr int kLegendSample = 22; // a pen's sample line
constexpr int kLegendGap = 4;     // between the sample and the text

} // namespace stepdeck::ui::pathviewlayout
