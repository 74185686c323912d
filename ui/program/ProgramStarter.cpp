#include "ProgramStarter.h"
#include "machine/Machine.h"

namespace stepdeck::ui {

ProgramStarter::ProgramStarter(QObject* parent)
    : QObject(parent), m_check(new ProgramBackgroundCheck(this))
{
    connect(m_check, &ProgramBackgroundCheck::checked, this, &ProgramStarter::onChecked);
    connect(m_check, &ProgramBackgroundCheck::progress, this, &ProgramStarter::progress);
}

bool ProgramStarter::request(program::ProgramRunner* runner, const program::Program& program,
                             int fromLine, bool stepOnly, QString* why)
{
    if (m_pending || !runner || !runner->claimMotion(why))
        return false;
    m_runner = runner;
    m_program = program;
    m_fromLine = fromLine;
    m_stepOnly = stepOnly;
    m_facts = runner->startFacts();
    m_pending = true;
    m_abort = connect(runner->machine(), &machine::Machine::abortRequested, this,
                      [this] { cancel(m_stopReason); });
    m_check->start(program, m_facts, fromLine);
    return true;
}

void ProgramStarter::endRequest()
{
    m_pending = false;
    disconnect(m_abort);
    if (m_runner)
        m_runner->releaseMotion(); // nothing unless its run started
}

void ProgramStarter::cancel(const QString& reason)
{
    if (!m_pending)
        return;
    m_check->cancel();
    endRequest();
    Q_EMIT refused({program::ProgramError{
        0, 0, reason.isEmpty() ? program::ProgramRunner::tr("the check was cancelled") : reason}});
}

void ProgramStarter::onChecked(const program::ProgramCheckResult& result)
{
    if (!m_pending)
        return;
    disconnect(m_abort);
    m_pending = false;
    QList<program::ProgramError> errors;
    if (!m_runner) {
        Q_EMIT refused({program::ProgramError{0, 0, tr("the machine was closed")}});
        return;
    }
    // startChecked gives the machine's motion back when it refuses.
    if (m_runner->startChecked(m_program, m_fromLine, m_facts, result, &errors, m_stepOnly))
        Q_EMIT started(m_program);
    else
        Q_EMIT refused(errors);
}

} // namespace stepdeck::ui
