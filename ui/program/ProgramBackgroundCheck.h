#pragma once
#include "program/ProgramCheck.h"
#include <QFutureWatcher>
#include <QObject>

namespace stepdeck::ui {

// Parses and checks a program's text off the GUI thread (issue 20): a CAM program of 200 000
// lines takes the parser most of a second, which must not freeze STOP and PANIC while the
// operator types. Only the newest request reports (checked()); an older one still running is
// dropped when it ends. Pure inputs: the text, the machine's axis names and its facts.
class ProgramBackgroundCheck : public QObject
{
    Q_OBJECT
public:
    explicit ProgramBackgroundCheck(QObject* parent = nullptr);

    void start(const QByteArray& text, const QStringList& axisNames,
               const program::MachineFacts& facts);
    void cancel(); // the running request reports nothing
    bool isChecking() const { return m_checking; }

    // The parse and the check in one: the parser's errors, or the check's result.
    static program::ProgramCheckResult run(const QByteArray& text, const QStringList& axisNames,
                                           const program::MachineFacts& facts);

Q_SIGNALS:
    void checked(const stepdeck::program::ProgramCheckResult& result);

private:
    QFutureWatcher<program::ProgramCheckResult> m_watcher;
    bool m_checking = false;
};

} // namespace stepdeck::ui
