#include "core/StopSignals.H"

#include <csignal>

namespace gpic {

namespace {
volatile std::sig_atomic_t receivedSignal = 0;
struct sigaction previousInt {}, previousTerm {}, previousHup {}, previousPipe {}, previousXfsz {};

extern "C" void raiseStopFlag(int signal) { receivedSignal = signal; }
} // namespace

StopSignals::StopSignals()
{
    receivedSignal = 0;
    struct sigaction action {};
    action.sa_handler = raiseStopFlag;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND | SA_RESTART;  // the second signal: the default action
    sigaction(SIGINT, &action, &previousInt);
    sigaction(SIGTERM, &action, &previousTerm);
    sigaction(SIGHUP, &action, &previousHup);  // the terminal closed: stop as on SIGTERM
    // A closed output pipe (picSolver | head) and a file-size limit (ulimit -f) would kill the
    // process mid-write without its state; ignored, they come back as write errors (EPIPE,
    // EFBIG), which the writers report in one line, leaving the last good state on disk.
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    sigaction(SIGPIPE, &ignore, &previousPipe);
    sigaction(SIGXFSZ, &ignore, &previousXfsz);
}

StopSignals::~StopSignals()
{
    sigaction(SIGINT, &previousInt, nullptr);
    sigaction(SIGTERM, &previousTerm, nullptr);
    sigaction(SIGHUP, &previousHup, nullptr);
    sigaction(SIGPIPE, &previousPipe, nullptr);
    sigaction(SIGXFSZ, &previousXfsz, nullptr);
}

int StopSignals::received() { return receivedSignal; }

std::string StopSignals::name(int signal)
{
    return signal == SIGINT    ? "SIGINT"
           : signal == SIGTERM ? "SIGTERM"
           : signal == SIGHUP  ? "SIGHUP"
                               : "signal " + std::to_string(signal);
}

} // namespace gpic
