#include "ForcePlot.H"

#include "Gnuplot.H"
#include "core/error.H"

#include <sstream>

namespace gpic {

namespace {

std::string header(const std::string& pngPath)
{
    return "set datafile separator ','\nset terminal pngcairo size 900,600 noenhanced font ',10'\n"
           "set output " + gnuplotQuoted(pngPath) + "\nset grid\nset key outside right top\n";
}

} // namespace

bool plotForces(const ForceSeries& series, const std::string& csvPath, const std::string& pngPath,
                bool againstDisplacement)
{
    // A 3D case's forces.dat has a third component, and its forces are not per metre.
    bool threeD = false;
    for (const auto& name : series.names) threeD = threeD || (name.size() > 3 && name.substr(name.size() - 3) == ":Fz");
    std::ostringstream script;
    script << header(pngPath)
           << "set title 'Force of the material on the rigid bodies (" << (againstDisplacement ? "against displacement" : "against time")
           << ")'\nset ylabel " << (threeD ? "'force [N]'" : "'force [N/m]'") << "\nset xlabel "
           << (againstDisplacement ? "'displacement |d| [m]'" : "'time [s]'") << "\nplot ";
    bool first = true;
    for (std::size_t c = 1; c < series.names.size(); ++c) {
        const std::string& name = series.names[c];
        const auto colon = name.rfind(':');
        const std::string body = name.substr(0, colon), what = name.substr(colon + 1);
        if (what != "Fx" && what != "Fy" && what != "Fz") continue;
        std::string x = "1";
        if (againstDisplacement) {
            const int dx = series.column(body + ":dx") + 1, dy = series.column(body + ":dy") + 1;
            x = "sqrt($" + std::to_string(dx) + "**2 + $" + std::to_string(dy) + "**2";
            if (const int dz = series.column(body + ":dz") + 1; dz > 0) x += " + $" + std::to_string(dz) + "**2";
            x += ")";
        }
        script << (first ? "" : ", \\\n     ") << gnuplotQuoted(csvPath) << " skip 1 using (" << (x == "1" ? "$1" : x)
               << "):" << c + 1 << " with lines lw 2 title " << gnuplotQuoted(name);
        first = false;
    }
    script << '\n';
    return runGnuplot(script.str(), pngPath, csvPath);
}

bool plotSurface(const std::string& csvPath, const std::string& pngPath, const std::string& title)
{
    std::ostringstream script;
    script << header(pngPath) << "set title " << gnuplotQuoted(title)
           << "\nset xlabel 'distance along the face s [m]'\nset ylabel 'stress [Pa]'\n"
           << "plot " << gnuplotQuoted(csvPath) << " skip 1 using 1:7 with linespoints pt 7 lw 2 title 'normal stress', \\\n     "
           << gnuplotQuoted(csvPath) << " skip 1 using 1:8 with linespoints pt 5 lw 2 title 'shear stress'\n";
    return runGnuplot(script.str(), pngPath, csvPath);
}

bool plotWear(const std::string& csvPath, const std::string& pngPath, const std::vector<std::string>& faces,
              const std::string& title)
{
    std::ostringstream script;
    script << header(pngPath) << "set title " << gnuplotQuoted(title)
           << "\nset xlabel 'distance along the face s [m]'\nset ylabel 'wear depth [m]'\nplot ";
    for (std::size_t k = 0; k < faces.size(); ++k)
        script << (k ? ", \\\n     " : "") << gnuplotQuoted(csvPath) << " skip 1 using 2:($1 == " << k
               << " ? $5 : 1/0) with linespoints pt 7 lw 2 title " << gnuplotQuoted(faces[k]);
    script << '\n';
    return runGnuplot(script.str(), pngPath, csvPath);
}

} // namespace gpic
