#include "ProgramBackgroundCheck.h"
#include "program/ProgramRunner.h"
#include <QPromise>
#include <QThreadPool>
#include <memory>

namespace stepdeck::ui {

ProgramBackgroundCheck::ProgramBackgroundCheck(QObject* parent) : QObject(parent)
{
    // The watcher follows only the newest future: an older one ending reports nothing.
    connect(&m_watcher, &QFutureWatcher<program::ProgramCheckResult>::finished, this, [this] {
        if (!m_checking || m_watcher.future().isCanceled() || m_watcher.future().resultCount() == 0)
            return;
        m_checking = false;
        Q_EMIT checked(m_watcher.result());
    });
    connect(&m_watcher, &QFutureWatcher<program::ProgramCheckResult>::progressValueChanged, this,
            [this](int value) {
                if (m_checking)
                    Q_EMIT progress(value);
            });
}

ProgramBackgroundCheck::~ProgramBackgroundCheck()
{
    // A check still running ends at its next step; its result goes nowhere.
    m_watcher.future().cancel();
}

program::ProgramCheckResult ProgramBackgroundCheck::run(const program::ProgramSource& source,
                                                        const QStringList& axisNames,
                                                        const program::MachineFacts& facts,
                                                        const program::CheckProgress& progress)
{
    return program::ProgramCheck::check(source, axisNames, facts, 1, progress);
}

void ProgramBackgroundCheck::start(const program::ProgramSource& source,
                                   const QStringList& axisNames, const program::MachineFacts& facts)
{
    launch([source, axisNames, facts](const program::CheckProgress& progress) {
        return run(source, axisNames, facts, progress);
    });
}

void ProgramBackgroundCheck::start(const program::Program& program,
                                   const program::MachineFacts& facts, int fromLine)
{
    launch([program, facts, fromLine](const program::CheckProgress& progress) {
        return program::ProgramRunner::checkForStart(program, facts, fromLine, progress);
    });
}

void ProgramBackgroundCheck::launch(Job job)
{
    m_watcher.future().cancel(); // the one running is of an older request
    auto promise = std::make_shared<QPromise<program::ProgramCheckResult>>();
    promise->setProgressRange(0, kProgressSteps);
    promise->start();
    m_checking = true;
    m_watcher.setFuture(promise->future());
    QThreadPool::globalInstance()->start([promise, job = std::move(job)] {
        const program::CheckProgress progress = [&promise](qint64 done, qint64 total) {
            if (total > 0)
                promise->setProgressValue(int(done * kProgressSteps / total));
            return !promise->isCanceled();
        };
        program::ProgramCheckResult result = job(progress);
        if (!result.cancelled)
            promise->addResult(std::move(result));
        promise->finish();
    });
}

void ProgramBackgroundCheck::cancel()
{
    m_checking = false;
    m_watcher.future().cancel();
    m_watcher.setFuture(QFuture<program::ProgramCheckResult>());
}

} // namespace stepdeck::ui
