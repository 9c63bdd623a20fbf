#include "io/AtomicVtkWrite.H"

#include "core/error.H"
#include "io/VtkErrorGuard.H"

#include <vtkDataObject.h>
#include <vtkErrorCode.h>
#include <vtkNew.h>
#include <vtkXMLWriter.h>

#include <cerrno>
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
    int ok = 0;
    errno = 0;
    {
        QuietVtk quiet;  // one line of ours instead of VTK's log
        ok = writer->Write();
    }
    const int writeErrno = errno;
    std::error_code ec;
    if (!ok || errors->failed || writer->GetErrorCode() != 0) {
        // A full disk is what the user must hear of, with where (before the partial file goes).
        const auto space = std::filesystem::space(std::filesystem::path(tmp).parent_path(), ec);
        const bool full = writeErrno == ENOSPC || writer->GetErrorCode() == vtkErrorCode::OutOfDiskSpaceError ||
                          (!ec && space.available < 4096);
        std::filesystem::remove(tmp, ec);
        const std::string why = full ? "no space left on device"
                                     : (errors->first.empty() ? "VTK writer failed" : errors->first);
        throw RunError("cannot write " + what + " to " + path + ": " + why);
    }
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::filesystem::remove(tmp, ec);
        throw RunError("cannot write " + what + " to " + path + ": " + ec.message());
    }
}

} // namespace detail
} // namespace gpic
