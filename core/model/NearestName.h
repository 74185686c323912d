#pragma once
#include <QStringList>

namespace stepdeck::names {

// "Did you mean ...?" for names people type: commands, options, models and parameters
// (issue 16). Pure functions, shared by the CLI and the core's parameter messages.

// Optimal string alignment distance: insertions, deletions, substitutions and swaps of two
// neighbouring characters count one each ("stauts" -> "status" is 1). Case-insensitive.
int editDistance(QStringView a, QStringView b);

// The candidate `typed` most likely meant: the closest within 1 edit (3 characters typed)
// or 2 edits (more); failing that, the only candidate that `typed` begins. Equally close
// candidates: the first in the list. Empty when nothing is close, when `typed` is itself a
// candidate, or when it has fewer than 3 characters (too little to guess from).
QString nearest(const QString& typed, const QStringList& candidates);

} // namespace stepdeck::names
