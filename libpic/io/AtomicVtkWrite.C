#include "io/AtomicVtkWrite.H"

#include "core/error.H"
#include "io/VtkErrorGuard.H"

#include <vtkDataObject.h>
#include <vtkNew.h>
#include <vtkXMLWriter.h>

#include <filesystem>
#include <system_error>

namespace gpic {
namespace detail {

void writeXmlAtomically(vtkXMLWriter* writer, vtkDataObject* data, const std::string& path,
                        const std::string& what)
{
    const std::string tmp = path + ".tmp";
    vtkNew<ErrorCollector> errors;
    writer->AddObserver(vtkCommand::ErrorEvent, errors);
    writer->SetInputData(data);
    writer->SetFileName(tmp.c_str());
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();  // raw bytes: smaller, and Float64 stays bit-exact
    writer->SetHeaderTypeToUInt64();  // arrays over 4 GiB
    // Uncompressed: faster to write, and VTK 9.1 crashes (SIGFPE, huge allocations) on some
    // corrupt compressed-block headers instead of reporting an error.
    writer->SetCompressorTypeToNone();
    const int ok = writer->Write();
    std::error_code ec;
    if (!ok || errors->failed || writer->GetErrorCode() != 0) {
        std::filesystem::remove(tmp, ec);
        throw RunError("cannot write " + what + " to " + path + ": " +
                       (errors->first.empty() ? "VTK writer failed" : errors->first));
    }
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::filesystem::remove(tmp, ec);
        throw RunError("cannot write " + what + " to " + path + ": " + ec.message());
    }
}

} // namespace detail
} // namespace gpic
