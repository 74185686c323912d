#pragma once
// Shared by stepdeck-cli and stepdeck-sim (header-only: app/*/ sources are globbed per folder).
#include <QSocketNotifier>
#include <csignal>
#include <functional>
#include <sys/socket.h>
#include <unistd.h>

namespace stepdeck::app {

// Turns SIGINT/SIGTERM/SIGHUP into a call on the event loop (self-pipe: the handler only
// writes one byte), so an interrupted jog can still send its stop and the simulator can quit
// cleanly. SIGHUP (terminal closed, ssh dropped) must not kill a process mid-motion.
// One instance per process.
class SignalPipe
{
public:
    explicit SignalPipe(std::function<void(int)> onSignal) : m_onSignal(std::move(onSignal))
    {
        if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, s_fds) != 0)
            return;
        m_notifier = new QSocketNotifier(s_fds[1], QSocketNotifier::Read);
        QObject::connect(m_notifier, &QSocketNotifier::activated, m_notifier, [this] {
            unsigned char signalNumber = 0;
            if (::read(s_fds[1], &signalNumber, 1) == 1 && m_onSignal)
                m_onSignal(signalNumber);
        });
        struct sigaction action = {};
        action.sa_handler = &SignalPipe::handle;
        sigemptyset(&action.sa_mask);
        action.sa_flags = SA_RESTART;
        for (int signalNumber : kSignals)
            sigaction(signalNumber, &action, nullptr);
    }
    ~SignalPipe()
    {
        for (int signalNumber : kSignals)
            std::signal(signalNumber, SIG_DFL);
        delete m_notifier;
        for (int& fd : s_fds) {
            if (fd >= 0)
                ::close(fd);
            fd = -1;
        }
    }
    SignalPipe(const SignalPipe&) = delete;
    SignalPipe& operator=(const SignalPipe&) = delete;

    static constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

    // Further signals through the same pipe (the CLI's feed hold: SIGTSTP, SIGCONT), until
    // release(); a process without a SignalPipe keeps their defaults.
    static void catchAlso(int signalNumber)
    {
        if (s_fds[0] < 0)
            return;
        struct sigaction action = {};
        action.sa_handler = &SignalPipe::handle;
        sigemptyset(&action.sa_mask);
        action.sa_flags = SA_RESTART;
        sigaction(signalNumber, &action, nullptr);
    }
    static void release(int signalNumber) { std::signal(signalNumber, SIG_DFL); }

private:
    static void handle(int signalNumber)
    {
        const unsigned char byte = static_cast<unsigned char>(signalNumber);
        if (s_fds[0] >= 0) {
            const ssize_t written = ::write(s_fds[0], &byte, 1);
            (void)written; // nothing sensible to do in a signal handler
        }
    }

    static inline int s_fds[2] = {-1, -1};
    std::function<void(int)> m_onSignal;
    QSocketNotifier* m_notifier = nullptr;
};

} // namespace stepdeck::app
