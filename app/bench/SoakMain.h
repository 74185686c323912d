#pragma once
#include <QStringList>

namespace stepdeck::bench {

// stepdeck-bench --soak N / --replug N [--model M] [--seed S] [--json]. Returns the exit
// code, or -1 when args ask for neither (the classic benchmark then runs).
int soakMain(const QString& program, const QStringList& args);

} // namespace stepdeck::bench
