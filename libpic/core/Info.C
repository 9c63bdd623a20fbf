#include "core/Info.H"

#include <iostream>

namespace gpic {

namespace {
bool quiet_ = false;

//- A stream that discards what it is given (no buffer: every write fails silently).
std::ostream& sink()
{
    static std::ostream discard(nullptr);
    return discard;
}
} // namespace

std::ostream& info() { return quiet_ ? sink() : std::cout; }

void setQuiet(bool quiet) { quiet_ = quiet; }

} // namespace gpic
