#include "bodies/TimeFunction.H"

#include "core/error.H"
#include "dictionary/Dictionary.H"
#include "dictionary/TokenConversion.H"
#include "dictionary/Tokenizer.H"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace gpic {

namespace {

const Entry& entryOf(const Dictionary& dict, const std::string& keyword)
{
    const Entry* e = dict.findEntry(keyword);
    if (!e)
        throw InputError(dict.fileName(), dict.startLine(),
                         "keyword '" + keyword + "' is undefined in dictionary " + dict.name());
    if (e->dict) dict.fail(keyword, "keyword '" + keyword + "' in dictionary " + dict.name() +
                                        " needs a value, found a sub-dictionary");
    return *e;
}

bool isTable(const std::vector<Token>& tokens)
{
    return !tokens.empty() && tokens.front().kind == Token::Kind::word && tokens.front().text == "table";
}

//- The rows of `table (...)`, each with `columns` numbers and strictly increasing times.
std::vector<std::vector<double>> readTable(const Dictionary& dict, const std::string& keyword,
                                           const std::vector<Token>& tokens, std::size_t columns,
                                           const std::string& rowForm)
{
    const std::string where = "keyword '" + keyword + "' in dictionary " + dict.name() + ": ";
    std::vector<std::vector<double>> rows;
    const std::string problem = convertTokens(std::vector<Token>(tokens.begin() + 1, tokens.end()), rows);
    if (!problem.empty()) dict.fail(keyword, where + "table " + problem + "; write table (" + rowForm + " ...)");
    if (rows.empty()) dict.fail(keyword, where + "the table is empty; write table (" + rowForm + " ...)");
    for (std::size_t k = 0; k < rows.size(); ++k) {
        if (rows[k].size() != columns)
            dict.fail(keyword, where + "table row " + std::to_string(k + 1) + " has " +
                                   std::to_string(rows[k].size()) + " numbers; each row is " + rowForm);
        if (k > 0 && !(rows[k][0] > rows[k - 1][0]))
            dict.fail(keyword, where + "table times must increase strictly (row " + std::to_string(k + 1) + ")");
    }
    return rows;
}

TimeFunction column(const std::vector<std::vector<double>>& rows, std::size_t c)
{
    std::vector<double> t, v;
    for (const auto& r : rows) {
        t.push_back(r[0]);
        v.push_back(r[c]);
    }
    return TimeFunction(std::move(t), std::move(v));
}

//- A number or an "expression" token as a function.
bool readComponent(const Token& token, TimeFunction& f)
{
    if (token.kind == Token::Kind::string) {
        f = TimeFunction(Expression(token.text, token.file, token.line));
        return true;
    }
    double value = 0;
    if (token.kind == Token::Kind::word && convertTokens({token}, value).empty()) {
        f = TimeFunction(value);
        return true;
    }
    return false;
}

} // namespace

TimeFunction::TimeFunction(double value) : kind_(Kind::constant), constant_(value) {}

TimeFunction::TimeFunction(std::vector<double> times, std::vector<double> values)
    : kind_(Kind::table), times_(std::move(times)), values_(std::move(values))
{}

TimeFunction::TimeFunction(Expression expression)
    : kind_(Kind::expression), expression_(std::make_shared<const Expression>(std::move(expression)))
{}

TimeFunction TimeFunction::read(const Dictionary& dict, const std::string& keyword)
{
    const Entry& e = entryOf(dict, keyword);
    if (isTable(e.tokens)) return column(readTable(dict, keyword, e.tokens, 2, "(t value)"), 1);
    TimeFunction f;
    if (e.tokens.size() == 1 && readComponent(e.tokens.front(), f)) return f;
    double constant = 0;  // also a number with unit brackets
    if (convertTokens(e.tokens, constant).empty()) return TimeFunction(constant);
    dict.fail(keyword, "keyword '" + keyword + "' in dictionary " + dict.name() +
                           ": expected a number, an \"expression of t\" or table ((t value) ...), found '" +
                           writeTokens(e.tokens) + "'");
}

template <int D> std::array<TimeFunction, D> TimeFunction::readVector(const Dictionary& dict, const std::string& keyword)
{
    const Entry& e = entryOf(dict, keyword);
    const char* const form = D == 2 ? "(x y)" : "(x y z)";
    if (isTable(e.tokens)) {
        const auto rows = readTable(dict, keyword, e.tokens, D + 1, D == 2 ? "(t x y)" : "(t x y z)");
        std::array<TimeFunction, D> f;
        for (int a = 0; a < D; ++a) f[a] = column(rows, a + 1);
        return f;
    }
    // (x y [z]) with each component a number or an "expression of t".
    const auto& t = e.tokens;
    std::array<TimeFunction, D> f;
    bool ok = t.size() == static_cast<std::size_t>(D + 2) && isPunct(t[0], '(') && isPunct(t[D + 1], ')');
    for (int a = 0; ok && a < D; ++a) ok = readComponent(t[a + 1], f[a]);
    if (ok) return f;
    typename Space<D>::Vector constant;  // also accepts (x y 0) in the plane, and unit brackets
    if (convertTokens(t, constant).empty()) {
        for (int a = 0; a < D; ++a) f[a] = TimeFunction(constant[a]);
        return f;
    }
    dict.fail(keyword, "keyword '" + keyword + "' in dictionary " + dict.name() + ": expected " + form +
                           " with numbers or \"expressions of t\", or table ((t " + std::string(form + 1) +
                           " ...), found '" + writeTokens(t) + "'");
}

template std::array<TimeFunction, 2> TimeFunction::readVector<2>(const Dictionary&, const std::string&);
#if GPIC_WITH_3D
template std::array<TimeFunction, 3> TimeFunction::readVector<3>(const Dictionary&, const std::string&);
#endif

double TimeFunction::value(double t) const
{
    switch (kind_) {
    case Kind::constant: return constant_;
    case Kind::table: {
        if (t <= times_.front()) return values_.front();
        if (t >= times_.back()) return values_.back();
        const auto k = static_cast<std::size_t>(std::upper_bound(times_.begin(), times_.end(), t) - times_.begin());
        const double w = (t - times_[k - 1]) / (times_[k] - times_[k - 1]);
        return (1.0 - w) * values_[k - 1] + w * values_[k];
    }
    case Kind::expression: {
        const double v = (*expression_)(t);
        if (!std::isfinite(v)) {
            std::ostringstream msg;
            msg << "expression \"" << expression_->text() << "\" (" << expression_->location()
                << ") is " << v << " at t = " << t << " s";
            throw RunError(msg.str());
        }
        return v;
    }
    }
    return 0.0;
}

double TimeFunction::tableIntegralTo(double t) const
{
    // Before the first time the table holds its first value (negative area for t < t0).
    if (t <= times_.front()) return values_.front() * (t - times_.front());
    double sum = 0.0;
    for (std::size_t k = 1; k < times_.size(); ++k) {
        if (t <= times_[k]) return sum + 0.5 * (values_[k - 1] + value(t)) * (t - times_[k - 1]);
        sum += 0.5 * (values_[k - 1] + values_[k]) * (times_[k] - times_[k - 1]);
    }
    return sum + values_.back() * (t - times_.back());
}

double TimeFunction::integral(double t0, double t1) const
{
    if (t0 == t1) return 0.0;
    switch (kind_) {
    case Kind::constant: return constant_ * (t1 - t0);
    case Kind::table: return tableIntegralTo(t1) - tableIntegralTo(t0);
    case Kind::expression: {
        if (!expression_->dependsOnTime()) return value(t0) * (t1 - t0);
        const double fa = value(t0), fb = value(t1), fm = value(0.5 * (t0 + t1));
        const double whole = (t1 - t0) / 6.0 * (fa + 4.0 * fm + fb);
        const double scale = std::max({std::abs(fa), std::abs(fm), std::abs(fb), 1e-300});
        return adaptiveSimpson(t0, t1, fa, fm, fb, whole, 1e-12 * scale * std::abs(t1 - t0), 0);
    }
    }
    return 0.0;
}

double TimeFunction::adaptiveSimpson(double a, double b, double fa, double fm, double fb,
                                     double whole, double tolerance, int depth) const
{
    const double m = 0.5 * (a + b);
    const double flm = value(0.5 * (a + m)), frm = value(0.5 * (m + b));
    const double left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
    const double right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
    const double delta = left + right - whole;
    // At least 16 panels (a coarse sampling can miss a periodic function entirely), then
    // Richardson's correction once the halves agree or the recursion is deep enough.
    if (depth >= 4 && (depth >= 24 || std::abs(delta) <= 15.0 * tolerance))
        return left + right + delta / 15.0;
    return adaptiveSimpson(a, m, fa, flm, fm, left, 0.5 * tolerance, depth + 1) +
           adaptiveSimpson(m, b, fm, frm, fb, right, 0.5 * tolerance, depth + 1);
}

} // namespace gpic
