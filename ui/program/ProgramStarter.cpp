#include "ProgramStarter.h"

namespace stepdeck::ui {

ProgramStarter::ProgramStarter(QObject* parent)
    : QObject(parent), m_check(new ProgramBackgroundCheck(this))
{
    connect(m_check, &ProgramBackgroundCheck::checked, this, &ProgramStarter::onChecked);
    connect(m_check, &ProgramBackgroundCheck::progress, this, &ProgramStarter::progress);
}

bool ProgramStarter::request(program::ProgramRunner* runner, const program::Program& program,
                             int fromLine, bool stepOnly)
{
    if (m_pending || !runner)
        return false;
    m_runner = runner;
    m_program = program;
    m_fromLine = fromLine;
    m_stepOnly = stepOnly;
    m_facts = runner->startFacts();
    m_pending = true;
    m_check->start(program, m_facts, fromLine);
    return true;
}

void ProgramStarter::cancel(const QString& reason)
{
    if (!m_pending)
        return;
    m_check->cancel();
    m_pending = false;
    Q_EMIT refused({program::ProgramError{
        0, 0, reason.isEmpty() ? program::ProgramRunner::tr("the check was cancelled") : reason}});
}

void ProgramStarter::onChecked(const program::ProgramCheckResult& result)
{
    if (!m_pending)
        return;
    m_pending = false;
    QList<program::ProgramError> errors;
    if (!m_runner) {
        Q_EMIT refused({program::ProgramError{0, 0, tr("the machine was closed")}});
        return;
    }
    if (m_runner->startChecked(m_program, m_fromLine, m_facts, result, &errors, m_stepOnly))
        Q_EMIT started(m_program);
    else
        Q_EMIT refused(errors);
}

} // namespace stepdeck::ui
