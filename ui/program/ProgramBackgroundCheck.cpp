#include "ProgramBackgroundCheck.h"
#include "program/ProgramParser.h"
#include <QPromise>
#include <QThreadPool>
#include <memory>

namespace stepdeck::ui {

ProgramBackgroundCheck::ProgramBackgroundCheck(QObject* parent) : QObject(parent)
{
    // The watcher follows only the newest future: an older one ending reports nothing.
    connect(&m_watcher, &QFutureWatcher<program::ProgramCheckResult>::finished, this, [this] {
        if (!m_checking || m_watcher.future().resultCount() == 0)
            return;
        m_checking = false;
        Q_EMIT checked(m_watcher.result());
    });
}

program::ProgramCheckResult ProgramBackgroundCheck::run(const QByteArray& text,
                                                        const QStringList& axisNames,
                                                        const program::MachineFacts& facts)
{
    program::ProgramCheckResult result;
    const std::optional<program::Program> parsed =
        program::ProgramParser::parse(text, axisNames, &result.errors);
    if (parsed)
        result = program::ProgramCheck::check(*parsed, facts);
    return result;
}

void ProgramBackgroundCheck::start(const QByteArray& text, const QStringList& axisNames,
                                   const program::MachineFacts& facts)
{
    auto promise = std::make_shared<QPromise<program::ProgramCheckResult>>();
    promise->start();
    m_checking = true;
    m_watcher.setFuture(promise->future());
    QThreadPool::globalInstance()->start([promise, text, axisNames, facts] {
        promise->addResult(run(text, axisNames, facts));
        promise->finish();
    });
}

void ProgramBackgroundCheck::cancel()
{
    m_checking = false;
    m_watcher.setFuture(QFuture<program::ProgramCheckResult>());
}

} // namespace stepdeck::ui
