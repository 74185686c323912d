#pragma once
#include "ProgramBackgroundCheck.h"
#include "program/ProgramRunner.h"
#include <QObject>
#include <QPointer>

namespace stepdeck::ui {

// Starts a program the way ProgramRunner::start does, with its check off the GUI thread
// (issue 29: a program of 10^7 lines takes seconds to check, and STOP, PANIC and the window
// must not wait for it): the machine's facts are taken now, checked in the background from the
// line the run starts at, and the run starts with that check (ProgramRunner::startChecked),
// which refuses it if the machine changed meanwhile. One request at a time. The runner holds
// the machine's motion from the request on (ProgramRunner::claimMotion: nothing else starts
// meanwhile), and the machine's STOP, PANIC or close cancels a request still being checked.
class ProgramStarter : public QObject
{
    Q_OBJECT
public:
    explicit ProgramStarter(QObject* parent = nullptr);

    // False (nothing asked) while a request is pending, or with *why when another holds the
    // machine's motion (an MDI line, a program).
    bool request(program::ProgramRunner* runner, const program::Program& program, int fromLine,
                 bool stepOnly, QString* why = nullptr);
    // What refused() says when the machine's STOP, PANIC or close cancelled the request.
    void setStopReason(const QString& reason) { m_stopReason = reason; }
    // The pending request ends without a start; refused() says why (`reason`, else "the check
    // was cancelled").
    void cancel(const QString& reason = {});
    bool isPending() const { return m_pending; }

Q_SIGNALS:
    void progress(int step); // 0..ProgramBackgroundCheck::kProgressSteps of the text read
    void started(const stepdeck::program::Program& program);
    void refused(const QList<stepdeck::program::ProgramError>& errors);

private:
    void onChecked(const program::ProgramCheckResult& result);
    void endRequest(); // not pending; the machine's motion given back unless the run started

    ProgramBackgroundCheck* m_check;
    QPointer<program::ProgramRunner> m_runner;
    program::Program m_program;
    program::MachineFacts m_facts;
    int m_fromLine = 1;
    bool m_stepOnly = false;
    bool m_pending = false;
    QString m_stopReason;
    QMetaObject::Connection m_abort; // the machine's abortRequested while pending
};

} // namespace stepdeck::ui
