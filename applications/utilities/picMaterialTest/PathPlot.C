#include "PathPlot.H"

#include "Gnuplot.H"
#include "core/error.H"

#include <algorithm>
#include <sstream>

namespace gpic {

bool plotPath(const std::string& csvPath, const std::string& pngPath, const std::string& title,
              const NaturalAxes& axes, int steps)
{
    const std::string data = gnuplotQuoted(csvPath) + " skip 1";
    // Mark about 20 points along each curve so that short or stationary paths show too.
    const std::string marks = " with linespoints pt 7 ps 0.6 pi " + std::to_string(std::max(1, steps / 20));
    std::ostringstream script;
    script << "set datafile separator ','\n"
           << "set terminal pngcairo size 1300,520 noenhanced font ',10'\n"
           << "set output " << gnuplotQuoted(pngPath) << '\n'
           << "set multiplot layout 1,2 title " << gnuplotQuoted(title) << '\n'
           << "set grid\nset key top left opaque\nset format y '%g'\nset format x '%g'\n"
           << "set xlabel " << gnuplotQuoted(axes.xLabel) << "\nset ylabel " << gnuplotQuoted(axes.yLabel) << '\n'
           << "plot ";
    for (std::size_t i = 0; i < axes.curves.size(); ++i)
        script << (i ? ", \\\n     " : "") << data << " using (" << axes.xExpression << "):("
               << axes.curves[i].expression << ")" << marks << " title " << gnuplotQuoted(axes.curves[i].title);
    script << "\nset xlabel 'p = -(sigma11 + sigma22 + sigma33)/3 [Pa]'\n"
           << "set ylabel 'q = sqrt(3 J2) [Pa]'\n"
           << "plot " << data << " using " << axes.pColumn << ':' << axes.qColumn << marks << " title 'stress path'\n"
           << "unset multiplot\n";

    return runGnuplot(script.str(), pngPath, "the CSV " + csvPath);
}

} // namespace gpic
