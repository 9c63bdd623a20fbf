#include "core/StopSignals.H"

#include <csignal>

namespace gpic {

namespace {
volatile std::sig_atomic_t receivedSignal = 0;
struct sigaction previousInt {}, previousTerm {};

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
}

StopSignals::~StopSignals()
{
    sigaction(SIGINT, &previousInt, nullptr);
    sigaction(SIGTERM, &previousTerm, nullptr);
}

int StopSignals::received() { return receivedSignal; }

std::string StopSignals::name(int signal)
{
    return signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : "signal " + std::to_string(signal);
}

} // namespace gpic
