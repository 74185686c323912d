#pragma once
#include "program/ProgramCheck.h"
#include <QFutureWatcher>
#include <QObject>
#include <functional>

namespace stepdeck::ui {

// Parses and checks a program off the GUI thread (issue 20), in one pass over its source
// (issue 29: the editor's text, or a file too long to edit, read as it is checked): a CAM
// program of millions of lines takes seconds, which must not freeze STOP and PANIC. Only the
// newest request reports (checked()); starting another or cancel() ends the one running at its
// next progress step. progress() says how far it is. Pure inputs: the source, the machine's axis
// names and its facts.
class ProgramBackgroundCheck : public QObject
{
    Q_OBJECT
public:
    static constexpr int kProgressSteps = 1000;

    explicit ProgramBackgroundCheck(QObject* parent = nullptr);
    ~ProgramBackgroundCheck() override;

    void start(const program::ProgramSource& source, const QStringList& axisNames,
               const program::MachineFacts& facts);
    void start(const QByteArray& text, const QStringList& axisNames,
               const program::MachineFacts& facts)
    {
        start(program::ProgramSource::bytes(text), axisNames, facts);
    }
    // The check before a run (ProgramRunner::checkForStart): a program read before, from a line.
    void start(const program::Program& program, const program::MachineFacts& facts, int fromLine);
    void cancel(); // the running request stops and reports nothing
    bool isChecking() const { return m_checking; }

    // The parse and the check in one pass: the parser's errors, or the check's result.
    static program::ProgramCheckResult run(const program::ProgramSource& source,
                                           const QStringList& axisNames,
                                           const program::MachineFacts& facts,
                                           const program::CheckProgress& progress = {});

Q_SIGNALS:
    void checked(const stepdeck::program::ProgramCheckResult& result);
    void progress(int step); // 0..kProgressSteps of the text read

private:
    using Job = std::function<program::ProgramCheckResult(const program::CheckProgress&)>;
    void launch(Job job);

    QFutureWatcher<program::ProgramCheckResult> m_watcher;
    bool m_checking = false;
};

} // namespace stepdeck::ui
