#include "bodies/Expression.H"

#include "core/error.H"

#include <muParser.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <mutex>

namespace gpic {

namespace {
constexpr double pi = 3.14159265358979323846;

// muparser's abs keeps the sign of -0; std::abs, as before, does not.
double absolute(double v) { return std::abs(v); }

//- Nesting bound: muparser itself would take any depth, but such input is a mistake.
constexpr int maxDepth = 200;
} // namespace

struct Expression::Engine {
    mu::Parser parser;
    double t = 0, x = 0, y = 0, z = 0;
    //- muparser evaluates with buffers of its own: one evaluation at a time (the threads of a
    //  step may ask a driver for its velocity together).
    std::mutex mutex;
};

std::string Expression::validNames(Variables variables)
{
    const char* const names = variables == Variables::time    ? "t"
                              : variables == Variables::plane ? "x, y"
                                                              : "x, y, z";
    return std::string(names) + ", pi, sin, cos, exp, sqrt, abs, tan, asin, acos, atan, sinh, cosh, tanh, "
                                "log, ln, log10, log2, sign, rint, min, max, sum, avg";
}

Expression::Expression(const std::string& text, const std::string& file, int line, Variables variables)
    : text_(text), file_(file), line_(line), variables_(variables), engine_(std::make_unique<Engine>())
{
    int depth = 0, deepest = 0;
    for (std::size_t i = 0; i < text_.size(); ++i) {
        depth += text_[i] == '(' ? 1 : text_[i] == ')' ? -1 : 0;
        deepest = std::max(deepest, depth);
        if (deepest > maxDepth) fail("nesting deeper than " + std::to_string(maxDepth) + " levels", static_cast<int>(i));
    }
    // muparser's `=` assigns to a variable: in a dictionary it can only be a mistake.
    for (std::size_t i = 0; i < text_.size(); ++i)
        if (text_[i] == '=' && (i == 0 || std::string("=<>!").find(text_[i - 1]) == std::string::npos) &&
            (i + 1 == text_.size() || text_[i + 1] != '='))
            fail("'=' assigns, which an expression may not (a comparison is ==)", static_cast<int>(i));
    mu::Parser& p = engine_->parser;
    // As written, in the order written: the optimizer would fold 0.1*t/3 into t*(0.1/3).
    p.EnableOptimizer(false);
    p.DefineConst("pi", pi);
    p.DefineFun("abs", absolute);
    if (variables == Variables::time) {
        p.DefineVar("t", &engine_->t);
    } else {
        p.DefineVar("x", &engine_->x);
        p.DefineVar("y", &engine_->y);
        if (variables == Variables::space) p.DefineVar("z", &engine_->z);
    }
    try {
        p.SetExpr(text_);
        p.Eval();  // muparser parses on the first evaluation: the mistakes show now
        usesTime_ = p.GetUsedVar().count("t") > 0;
    } catch (const mu::Parser::exception_type& e) {
        const std::string token = e.GetToken();
        const int position = std::max(0, static_cast<int>(e.GetPos()));
        switch (e.GetCode()) {
        case mu::ecUNASSIGNABLE_TOKEN: {
            const auto& functions = p.GetFunDef();
            if (functions.count(token)) fail("'" + token + "' needs an argument in ( )", position);
            fail("unknown name '" + token + "'", position);
        }
        case mu::ecEMPTY_EXPRESSION: fail("empty expression", 0);
        case mu::ecUNEXPECTED_EOF: fail("unexpected end", static_cast<int>(text_.size()));
        case mu::ecMISSING_PARENS: fail("missing ')'", position);
        default: {
            // muparser's own words, less its "at position N" (the message gives the character).
            std::string what = e.GetMsg();
            for (const char* tail : {" found at position", " at expression position", " at position"}) {
                const auto at = what.find(tail);
                if (at != std::string::npos) what.erase(at);
            }
            while (!what.empty() && (what.back() == '.' || what.back() == ' ')) what.pop_back();
            if (!what.empty()) what[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(what[0])));
            fail(what, position);
        }
        }
    }
}

Expression::Expression(Expression&&) noexcept = default;
Expression& Expression::operator=(Expression&&) noexcept = default;
Expression::~Expression() = default;

double Expression::at(double t, double x, double y, double z) const
{
    std::lock_guard<std::mutex> lock(engine_->mutex);
    engine_->t = t;
    engine_->x = x;
    engine_->y = y;
    engine_->z = z;
    return engine_->parser.Eval();
}

std::string Expression::location() const
{
    return line_ > 0 ? file_ + ":" + std::to_string(line_) : file_;
}

void Expression::fail(const std::string& what, int position) const
{
    throw InputError(file_, line_,
                     "expression \"" + text_ + "\": " + what + " at character " + std::to_string(position + 1) +
                         "; valid names: " + validNames(variables_) + "; operators + - * / ^ and ( )");
}

} // namespace gpic
