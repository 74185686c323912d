#pragma once
#include <QString>
#include <QtGlobal>
#include <cstdio>

namespace stepdeck::bench {

// One line to stream, flushed at once (a pipe sees the figures as they come).
void print(FILE* stream, const QString& text);
// A message handler that lets only critical and fatal messages through (to stderr): the
// figures on stdout stay readable.
void quiet(QtMsgType type, const QMessageLogContext& context, const QString& message);

} // namespace stepdeck::bench
