#include "io/VtkErrorGuard.H"

#include <vtkObject.h>

namespace gpic {
namespace detail {

void ErrorCollector::Execute(vtkObject*, unsigned long event, void* callData)
{
    if (event != vtkCommand::ErrorEvent) return;
    std::string text = callData ? static_cast<const char*>(callData) : "unknown VTK error";
    // VTK prefixes "ERROR: In file.cxx, line N\nClass (0x...): "; keep only the message.
    const auto colon = text.rfind("): ");
    if (colon != std::string::npos) text = text.substr(colon + 3);
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    if (first.empty()) first = text;
    failed = true;
}

QuietVtk::QuietVtk() : previous_(vtkObject::GetGlobalWarningDisplay())
{
    vtkObject::GlobalWarningDisplayOff();
}

QuietVtk::~QuietVtk() { vtkObject::SetGlobalWarningDisplay(previous_); }

} // namespace detail
} // namespace gpic
