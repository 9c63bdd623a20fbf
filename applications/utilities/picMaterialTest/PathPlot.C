#include "PathPlot.H"

#include "core/error.H"

#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <sstream>

namespace gpic {

namespace {
//- A gnuplot single-quoted string: a quote inside is written twice.
std::string quoted(const std::string& text)
{
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
    return out + "'";
}
} // namespace

bool plotPath(const std::string& csvPath, const std::string& pngPath, const std::string& title,
              const NaturalAxes& axes, int steps)
{
    const std::string data = quoted(csvPath) + " skip 1";
    // Mark about 20 points along each curve so that short or stationary paths show too.
    const std::string marks = " with linespoints pt 7 ps 0.6 pi " + std::to_string(std::max(1, steps / 20));
    std::ostringstream script;
    script << "set datafile separator ','\n"
           << "set terminal pngcairo size 1300,520 noenhanced font ',10'\n"
           << "set output " << quoted(pngPath) << '\n'
           << "set multiplot layout 1,2 title " << quoted(title) << '\n'
           << "set grid\nset key top left opaque\nset format y '%g'\nset format x '%g'\n"
           << "set xlabel " << quoted(axes.xLabel) << "\nset ylabel " << quoted(axes.yLabel) << '\n'
           << "plot ";
    for (std::size_t i = 0; i < axes.curves.size(); ++i)
        script << (i ? ", \\\n     " : "") << data << " using (" << axes.xExpression << "):("
               << axes.curves[i].expression << ")" << marks << " title " << quoted(axes.curves[i].title);
    script << "\nset xlabel 'p = -(sigma11 + sigma22 + sigma33)/3 [Pa]'\n"
           << "set ylabel 'q = sqrt(3 J2) [Pa]'\n"
           << "plot " << data << " using 9:10" << marks << " title 'stress path'\n"
           << "unset multiplot\n";

    std::error_code ec;
    std::filesystem::remove(pngPath, ec);
    FILE* gnuplot = popen("gnuplot > /dev/null 2>&1", "w");
    int status = -1;
    if (gnuplot) {
        const std::string text = script.str();
        std::fwrite(text.data(), 1, text.size(), gnuplot);
        status = pclose(gnuplot);
    }
    const bool ok = status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 0 &&
                    std::filesystem::exists(pngPath, ec);
    if (!ok)
        warning("", 0, "gnuplot did not draw " + pngPath + " (is gnuplot installed?); the CSV " +
                           csvPath + " has all the data");
    return ok;
}

} // namespace gpic
