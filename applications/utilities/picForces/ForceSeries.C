#include "ForceSeries.H"

#include "GridContactForces.H"

#include "core/error.H"
#include "io/TimeDirectories.H"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace gpic {

namespace fs = std::filesystem;

namespace {

bool parseNumber(const std::string& word, double& value)
{
    const char* text = word.c_str();
    char* end = nullptr;
    errno = 0;
    value = std::strtod(text, &end);
    return end != text && *end == '\0' && errno != ERANGE;
}

} // namespace

std::vector<std::pair<std::string, std::string>> outputFilesOfFunctions(const std::string& caseDir,
                                                                        const std::string& fileName)
{
    std::vector<std::pair<std::string, std::string>> found;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(fs::path(caseDir) / "postProcessing", ec)) {
        if (!e.is_directory() || e.path().filename() == "picForces") continue;
        const std::string f = latestOutputFile(e.path(), fileName);
        if (!f.empty()) found.emplace_back(e.path().filename().string(), f);
    }
    return found;
}

std::string latestOutputFile(const fs::path& functionDir, const std::string& fileName)
{
    std::error_code ec;
    double best = -HUGE_VAL;
    std::string found;
    for (const auto& e : fs::directory_iterator(functionDir, ec)) {
        double t = 0;
        if (!e.is_directory() || !parseNumber(e.path().filename().string(), t)) continue;
        if (t > best && fs::is_regular_file(e.path() / fileName)) {
            best = t;
            found = (e.path() / fileName).string();
        }
    }
    return found;
}

int ForceSeries::column(const std::string& name) const
{
    for (std::size_t c = 0; c < names.size(); ++c)
        if (names[c] == name) return static_cast<int>(c);
    return -1;
}

std::string defaultForcesFile(const std::string& caseDir)
{
    const fs::path post = fs::path(caseDir) / "postProcessing";
    const std::string preferred = latestOutputFile(post / "forces", "forces.dat");
    if (!preferred.empty()) return preferred;
    const auto found = outputFilesOfFunctions(caseDir, "forces.dat");
    if (found.size() == 1) return found.front().second;
    if (found.empty())
        throw InputError((post / "forces").string(), 0,
                         "no <time>/forces.dat: add a forces function object to system/controlDict "
                         "(functions { forces { type forces; } }), run the solver, or give -file");
    std::string list;
    for (const auto& f : found) list += (list.empty() ? "" : ", ") + f.first;
    throw InputError(post.string(), 0, "several function objects wrote forces.dat (" + list +
                                           "): choose one with -file postProcessing/<name>/<time>/forces.dat");
}

ForceSeries readForcesFile(const std::string& path)
{
    std::ifstream in(path);
    if (!in) throw InputError(path, 0, "cannot open file");
    ForceSeries s;
    s.source = path;
    std::string line;
    int lineNo = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        std::istringstream words(line);
        std::string w;
        if (line.rfind('#', 0) == 0) {
            std::vector<std::string> names;
            words >> w;  // the '#'
            if (w.size() > 1) names.push_back(w.substr(1));
            while (words >> w) names.push_back(w);
            if (!names.empty() && names.front() == "time") {
                s.names = names;
                s.columns.assign(names.size(), {});
            }
            continue;
        }
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        if (s.names.empty())
            throw InputError(path, lineNo, "data before the header line '# time ...'");
        std::vector<double> row;
        while (words >> w) {
            double v = 0;
            if (!parseNumber(w, v)) throw InputError(path, lineNo, "'" + w + "' is not a number");
            row.push_back(v);
        }
        if (row.size() != s.names.size())
            throw InputError(path, lineNo, "row has " + std::to_string(row.size()) + " values, the header names " +
                                               std::to_string(s.names.size()) + " columns");
        for (std::size_t c = 0; c < row.size(); ++c) s.columns[c].push_back(row[c]);
    }
    if (s.names.empty()) throw InputError(path, 0, "no header line '# time ...': not a forces.dat file");
    if (s.samples() == 0) throw InputError(path, 0, "no rows yet: the run has not written any forces");
    return s;
}

ForceSeries gridForceSeries(const std::string& caseDir, const Vector2& CofR)
{
    ForceSeries s;
    s.names = {"time", "all:Fx", "all:Fy", "all:Mz"};
    s.columns.assign(4, {});
    s.source = (fs::path(caseDir) / "<time>/grid.vti").string();
    for (const auto& [t, name] : listTimeDirectories(caseDir)) {
        const fs::path file = fs::path(caseDir) / name / "grid.vti";
        if (!fs::exists(file)) continue;
        const GridContactForces g = readGridContactForces(file.string());
        Vector2 F = Vector2::Zero();
        double M = 0.0;
        for (std::size_t n = 0; n < g.force.size(); ++n) {
            const Vector2 r = g.position[n] - CofR;
            F += g.force[n];
            M += r.x() * g.force[n].y() - r.y() * g.force[n].x();
        }
        s.columns[0].push_back(t);
        s.columns[1].push_back(F.x());
        s.columns[2].push_back(F.y());
        s.columns[3].push_back(M);
    }
    if (s.samples() == 0)
        throw InputError(caseDir, 0, "no time directory has a grid.vti: set writeGrid yes in system/controlDict");
    return s;
}

void writeCsv(const ForceSeries& series, const std::string& path)
{
    std::ofstream out(path);
    out.precision(10);
    for (std::size_t c = 0; c < series.names.size(); ++c) out << (c ? "," : "") << series.names[c];
    out << '\n';
    for (std::size_t k = 0; k < series.samples(); ++k) {
        for (std::size_t c = 0; c < series.columns.size(); ++c) out << (c ? "," : "") << series.columns[c][k];
        out << '\n';
    }
    if (!out) throw RunError("cannot write " + path);
}

std::vector<double> windowMean(const ForceSeries& series, double t0, double t1, std::size_t& used)
{
    const auto& t = series.columns.front();
    std::vector<std::size_t> in;
    for (std::size_t k = 0; k < t.size(); ++k)
        if (t[k] >= t0 && t[k] <= t1) in.push_back(k);
    used = in.size();
    if (in.empty()) {
        std::ostringstream msg;
        msg << "-window " << t0 << ' ' << t1 << ": no sample in the window; " << series.source << " spans t = "
            << t.front() << " ... " << t.back() << " s";
        throw InputError("", 0, msg.str());
    }
    std::vector<double> mean(series.columns.size(), 0.0);
    for (std::size_t c = 0; c < series.columns.size(); ++c) {
        const auto& v = series.columns[c];
        const double span = t[in.back()] - t[in.front()];
        if (!(span > 0.0)) {  // one sample (or all at one time)
            for (std::size_t k : in) mean[c] += v[k] / static_cast<double>(in.size());
            continue;
        }
        double area = 0.0;
        for (std::size_t i = 1; i < in.size(); ++i)
            area += 0.5 * (v[in[i]] + v[in[i - 1]]) * (t[in[i]] - t[in[i - 1]]);
        mean[c] = area / span;
    }
    return mean;
}

} // namespace gpic
