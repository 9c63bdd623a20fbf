#include "plasticity/HardeningTable.H"

#include "dictionary/Dictionary.H"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace gpic {

namespace {
std::string number(double v)
{
    std::ostringstream s;
    s << std::setprecision(6) << v;
    return s.str();
}
} // namespace

HardeningTable::HardeningTable(double value) : x_{0.0}, y_{value} {}

HardeningTable::HardeningTable(const Dictionary& dict, const std::string& keyword,
                               const std::function<bool(double)>& valid,
                               const std::string& requirement)
{
    const auto rows = dict.get<std::vector<std::vector<double>>>(keyword);
    const std::string where = "keyword '" + keyword + "' in dictionary " + dict.name() + ": ";
    if (rows.empty()) dict.fail(keyword, where + "the table is empty; expected ((x0 y0) (x1 y1) ...)");
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const std::string row = "row " + std::to_string(i + 1);
        if (rows[i].size() != 2)
            dict.fail(keyword, where + row + " has " + std::to_string(rows[i].size()) +
                                   " values; expected pairs (x y)");
        if (i > 0 && !(rows[i][0] > rows[i - 1][0]))
            dict.fail(keyword, where + row + ": x must increase strictly down the table");
        if (!valid(rows[i][1]))
            dict.fail(keyword, where + row + ": value " + number(rows[i][1]) +
                                   " is not valid; requires " + requirement);
        x_.push_back(rows[i][0]);
        y_.push_back(rows[i][1]);
    }
}

double HardeningTable::operator()(double x) const
{
    if (x <= x_.front()) return y_.front();
    if (x >= x_.back()) return y_.back();
    const auto hi = static_cast<std::size_t>(std::upper_bound(x_.begin(), x_.end(), x) - x_.begin());
    const std::size_t lo = hi - 1;
    const double t = (x - x_[lo]) / (x_[hi] - x_[lo]);
    return y_[lo] + t * (y_[hi] - y_[lo]);
}

} // namespace gpic
