#include "functionObjects/FunctionObject.H"

#include "core/error.H"
#include "dictionary/Dictionary.H"
#include "io/DataRows.H"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <cstdlib>
#include <filesystem>
#include <limits>

namespace gpic {

std::string choiceList(const std::vector<std::string>& names)
{
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    return list.empty() ? "(none)" : list;
}

template <int D>
FunctionObject<D>::FunctionObject(const Dictionary& dict, const RunContext& context)
    : name_(dict.name().substr(dict.name().find_last_of('/') + 1)), context_(context),
      writeInterval_(dict.found("writeInterval")
                         ? dict.getChecked<long>("writeInterval", [](const long& n) { return n > 0; },
                                                 "writeInterval >= 1 (steps)")
                         : 1)
{}

template <int D>
void FunctionObject<D>::execute(const MpmSolver<D>& solver, double time, long step)
{
    if (step % writeInterval_ == 0) write(solver, time);
}

template <int D>
std::optional<double> FunctionObject<D>::readFactor(const Dictionary& dict)
{
    if (!dict.found("factor")) return std::nullopt;
    return dict.getChecked<double>("factor", [](const double& f) { return f > 0; }, "factor > 0");
}

template <int D>
std::vector<int> FunctionObject<D>::bodyIds(const Dictionary& dict, const std::string& keyword) const
{
    std::vector<int> ids;
    const auto& names = context_.bodyNames;
    for (const auto& n : dict.getOrDefault<std::vector<std::string>>(keyword, {})) {
        const auto it = std::find(names.begin(), names.end(), n);
        if (it == names.end())
            dict.fail(keyword, dict.get<std::string>("type") + " " + name_ + ": '" + n +
                                   "' is not a body; valid choices: " + choiceList(names));
        ids.push_back(static_cast<int>(it - names.begin()));
    }
    return ids;
}

template <int D> std::filesystem::path FunctionObject<D>::directory() const
{
    return std::filesystem::path(context_.caseDir) / "postProcessing" / name_ / context_.startTimeName;
}

template <int D> void FunctionObject<D>::flushFiles()
{
    for (auto& [fileName, stream] : files_) {
        errno = 0;
        stream->flush();
        if (!*stream)
            throw RunError("cannot write " + (directory() / fileName).string() + ": " +
                           (errno ? std::strerror(errno) : "the stream failed"));
    }
}

template <int D> std::size_t FunctionObject<D>::keepRowsUpTo(double time)
{
    namespace fs = std::filesystem;
    const fs::path root = fs::path(context_.caseDir) / "postProcessing" / name_;
    std::error_code ec;
    if (!fs::is_directory(root, ec)) return 0;
    std::size_t dropped = 0;
    for (const auto& start : fs::directory_iterator(root)) {
        const std::string startName = start.path().filename().string();
        char* end = nullptr;
        const double startTime = std::strtod(startName.c_str(), &end);
        if (startName.empty() || *end != '\0' || !std::isfinite(startTime) || !start.is_directory(ec)) continue;
        // A start at or after `time` holds only later rows: its header lines are kept.
        const double upTo = startTime < time ? time : -std::numeric_limits<double>::infinity();
        for (const auto& entry : fs::directory_iterator(start.path())) {
            // Not a temporary (a rewrite cut short by a kill leaves <file>.tmp).
            const std::string file = entry.path().filename().string();
            const bool temporary = file[0] == '.' || entry.path().extension() == ".tmp";
            if (entry.is_regular_file(ec) && !temporary) dropped += gpic::keepRowsUpTo(entry.path().string(), upTo);
        }
    }
    return dropped;
}

template <int D>
std::ofstream& FunctionObject<D>::file(const std::string& fileName)
{
    for (auto& [n, f] : files_)
        if (n == fileName) return *f;
    namespace fs = std::filesystem;
    const fs::path dir = directory();
    fs::create_directories(dir);
    auto stream = std::make_unique<std::ofstream>(dir / fileName);
    if (!*stream) throw InputError((dir / fileName).string(), 0, "cannot open for writing");
    stream->precision(12);
    files_.emplace_back(fileName, std::move(stream));
    return *files_.back().second;
}

template <int D>
std::unique_ptr<FunctionObject<D>> FunctionObject<D>::New(const Dictionary& dict, const RunContext& context)
{
    return Registry<FunctionObject<D>>::select(dict, dict, context);
}

template class FunctionObject<2>;
#if GPIC_WITH_3D
template class FunctionObject<3>;
#endif

} // namespace gpic
