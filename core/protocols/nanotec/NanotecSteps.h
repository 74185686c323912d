#pragma once
#include "model/CommandResult.h"
#include <QList>
#include <QString>
#include <functional>
#include <memory>

namespace stepdeck::nanotec {

struct Reply;

// A request to the drives is a chain of steps: each runs one exchange (or a wait, or a piece
// of bookkeeping) and calls its Done with the outcome; the chain ends at the first failure.
struct Failure
{
    ErrorKind kind = ErrorKind::None;
    QString message;
    bool ok() const { return kind == ErrorKind::None; }
};
using Done = std::function<void(const Failure&)>;
using Step = std::function<void(const Done&)>;
using Check = std::function<Failure(const Reply&)>;

// Runs steps one after the other; done gets the first failure or success after the last.
void runSteps(QList<Step> steps, Done done);
// A step whose failures are logged and skipped (a cancel still ends the chain).
Step tolerant(Step step);
// A check that stores the reply's value and fails when it carries none.
Check sink(std::function<void(qint64)> store);

} // namespace stepdeck::nanotec
