#include "WearProfile.H"

#include "ForceSeries.H"

#include "core/error.H"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace gpic {

namespace fs = std::filesystem;

std::string defaultWearFile(const std::string& caseDir)
{
    const fs::path post = fs::path(caseDir) / "postProcessing";
    const auto found = outputFilesOfFunctions(caseDir, "wearProfile.dat");
    if (found.size() == 1) return found.front().second;
    if (found.empty())
        throw InputError(post.string(), 0,
                         "no <time>/wearProfile.dat: add a toolWear function object to system/controlDict "
                         "(functions { wear { type toolWear; body ...; faces { ... } } }), run the solver, or "
                         "give -file");
    std::string list;
    for (const auto& f : found) list += (list.empty() ? "" : ", ") + f.first;
    throw InputError(post.string(), 0, "several function objects wrote a wearProfile.dat (" + list + "): give -file");
}

WearProfile readWearProfile(const std::string& path)
{
    std::ifstream in(path);
    if (!in) throw InputError(path, 0, "cannot open the wear profile");
    WearProfile profile;
    profile.source = path;
    std::vector<std::pair<double, WearStation>> rows;
    int lineNumber = 0;
    for (std::string line; std::getline(in, line);) {
        ++lineNumber;
        if (line.empty()) continue;
        if (line[0] == '#') {
            // "...; face 0 front 1 back; ..." names the faces by index.
            const auto at = line.find("; face ");
            if (at != std::string::npos) {
                std::istringstream names(line.substr(at + 7, line.find(';', at + 1) - at - 7));
                int k;
                std::string name;
                while (names >> k >> name) {
                    if (k >= static_cast<int>(profile.faces.size())) profile.faces.resize(static_cast<std::size_t>(k) + 1);
                    profile.faces[static_cast<std::size_t>(k)] = name;
                }
            }
            continue;
        }
        std::istringstream row(line);
        double t;
        WearStation st;
        std::string extra;
        if (!(row >> t >> st.face >> st.s >> st.x >> st.y >> st.depth) || (row >> extra) || st.face < 0)
            throw InputError(path, lineNumber, "expected the six numbers time face s x y depth, found '" + line + "'");
        rows.emplace_back(t, st);
    }
    if (rows.empty()) throw InputError(path, 0, "no rows: has the run taken a step yet?");
    profile.time = rows.back().first;
    for (const auto& [t, st] : rows)
        if (t == profile.time) profile.stations.push_back(st);
    for (const auto& st : profile.stations)
        if (st.face >= static_cast<int>(profile.faces.size())) profile.faces.resize(static_cast<std::size_t>(st.face) + 1);
    for (std::size_t k = 0; k < profile.faces.size(); ++k)
        if (profile.faces[k].empty()) profile.faces[k] = "face" + std::to_string(k);
    return profile;
}

void writeWearCsv(const WearProfile& profile, const std::string& path)
{
    std::ofstream out(path);
    out.precision(10);
    out << "face,s,x,y,depth\n";
    for (const auto& st : profile.stations)
        out << st.face << ',' << st.s << ',' << st.x << ',' << st.y << ',' << st.depth << '\n';
    if (!out.flush()) throw RunError("cannot write " + path);
}

} // namespace gpic
