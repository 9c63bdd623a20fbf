#include "parallel/ProcessorDirectories.H"

namespace gpic {

std::vector<std::filesystem::path> processorDirectories(const std::string& caseDir)
{
    std::vector<std::filesystem::path> dirs;
    for (int k = 0;; ++k) {
        auto dir = std::filesystem::path(caseDir) / ("processor" + std::to_string(k));
        if (!std::filesystem::is_directory(dir)) return dirs;
        dirs.push_back(std::move(dir));
    }
}

} // namespace gpic
