#include "ForcePlot.H"

#include "core/error.H"

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <sstream>

namespace gpic {

namespace {

//- A gnuplot single-quoted string (a quote inside is doubled).
std::string quoted(const std::string& text)
{
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
    return out + "'";
}

bool runGnuplot(const std::string& script, const std::string& pngPath, const std::string& csvPath)
{
    std::error_code ec;
    std::filesystem::remove(pngPath, ec);
    FILE* gnuplot = popen("gnuplot > /dev/null 2>&1", "w");
    int status = -1;
    if (gnuplot) {
        std::fwrite(script.data(), 1, script.size(), gnuplot);
        status = pclose(gnuplot);
    }
    const bool ok = status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 0 &&
                    std::filesystem::exists(pngPath, ec);
    if (!ok)
        warning("", 0, "gnuplot did not draw " + pngPath + " (is gnuplot installed?); " + csvPath +
                           " has all the data");
    return ok;
}

std::string header(const std::string& pngPath)
{
    return "set datafile separator ','\nset terminal pngcairo size 900,600 noenhanced font ',10'\n"
           "set output " + quoted(pngPath) + "\nset grid\nset key outside right top\n";
}

} // namespace

bool plotForces(const ForceSeries& series, const std::string& csvPath, const std::string& pngPath,
                bool againstDisplacement)
{
    std::ostringstream script;
    script << header(pngPath)
           << "set title 'Force of the material on the rigid bodies (" << (againstDisplacement ? "against displacement" : "against time")
           << ")'\nset ylabel 'force [N/m]'\nset xlabel "
           << (againstDisplacement ? "'displacement |d| [m]'" : "'time [s]'") << "\nplot ";
    bool first = true;
    for (std::size_t c = 1; c < series.names.size(); ++c) {
        const std::string& name = series.names[c];
        const auto colon = name.rfind(':');
        const std::string body = name.substr(0, colon), what = name.substr(colon + 1);
        if (what != "Fx" && what != "Fy") continue;
        std::string x = "1";
        if (againstDisplacement) {
            const int dx = series.column(body + ":dx") + 1, dy = series.column(body + ":dy") + 1;
            x = "sqrt($" + std::to_string(dx) + "**2 + $" + std::to_string(dy) + "**2)";
        }
        script << (first ? "" : ", \\\n     ") << quoted(csvPath) << " skip 1 using (" << (x == "1" ? "$1" : x)
               << "):" << c + 1 << " with lines lw 2 title " << quoted(name);
        first = false;
    }
    script << '\n';
    return runGnuplot(script.str(), pngPath, csvPath);
}

bool plotSurface(const std::string& csvPath, const std::string& pngPath, const std::string& title)
{
    std::ostringstream script;
    script << header(pngPath) << "set title " << quoted(title)
           << "\nset xlabel 'distance along the face s [m]'\nset ylabel 'stress [Pa]'\n"
           << "plot " << quoted(csvPath) << " skip 1 using 1:7 with linespoints pt 7 lw 2 title 'normal stress', \\\n     "
           << quoted(csvPath) << " skip 1 using 1:8 with linespoints pt 5 lw 2 title 'shear stress'\n";
    return runGnuplot(script.str(), pngPath, csvPath);
}

} // namespace gpic
