#include "bodies/Expression.H"

#include "core/error.H"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace gpic {

namespace {
constexpr double pi = 3.14159265358979323846;
}

const char* Expression::validNames() { return "t, pi, sin, cos, exp, sqrt, abs"; }

Expression::Expression(const std::string& text, const std::string& file, int line)
    : text_(text), file_(file), line_(line)
{
    root_ = parseSum();
    skipBlanks();
    if (pos_ < text_.size()) fail(std::string("unexpected '") + text_[pos_] + "'");
    if (root_ < 0) fail("empty expression");
}

std::string Expression::location() const
{
    return line_ > 0 ? file_ + ":" + std::to_string(line_) : file_;
}

void Expression::fail(const std::string& what) const
{
    throw InputError(file_, line_,
                     "expression \"" + text_ + "\": " + what + " at character " +
                         std::to_string(pos_ + 1) + "; valid names: " + validNames() +
                         "; operators + - * / ^ and ( )");
}

int Expression::add(Op op, int a, int b, double value)
{
    nodes_.push_back(Node{op, value, a, b});
    return static_cast<int>(nodes_.size()) - 1;
}

void Expression::skipBlanks()
{
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
}

// sum := product (('+' | '-') product)*
int Expression::parseSum()
{
    int left = parseProduct();
    for (;;) {
        skipBlanks();
        if (pos_ >= text_.size() || (text_[pos_] != '+' && text_[pos_] != '-')) return left;
        const Op op = text_[pos_++] == '+' ? Op::add : Op::subtract;
        left = add(op, left, parseProduct());
    }
}

// product := unary (('*' | '/') unary)*
int Expression::parseProduct()
{
    int left = parseUnary();
    for (;;) {
        skipBlanks();
        if (pos_ >= text_.size() || (text_[pos_] != '*' && text_[pos_] != '/')) return left;
        const Op op = text_[pos_++] == '*' ? Op::multiply : Op::divide;
        left = add(op, left, parseUnary());
    }
}

// unary := ('+' | '-') unary | power      (so -t^2 = -(t^2))
int Expression::parseUnary()
{
    // Every nesting passes here: a bound keeps absurd input from exhausting the stack.
    struct Depth {
        int& d;
        explicit Depth(int& depth) : d(++depth) {}
        ~Depth() { --d; }
    } depth(depth_);
    if (depth_ > 200) fail("nesting deeper than 200 levels");
    skipBlanks();
    if (pos_ < text_.size() && (text_[pos_] == '-' || text_[pos_] == '+')) {
        const bool minus = text_[pos_++] == '-';
        const int operand = parseUnary();
        return minus ? add(Op::negate, operand) : operand;
    }
    return parsePower();
}

// power := primary ('^' unary)?          (right-associative: 2^3^2 = 2^9)
int Expression::parsePower()
{
    const int base = parsePrimary();
    skipBlanks();
    if (pos_ < text_.size() && text_[pos_] == '^') {
        ++pos_;
        return add(Op::power, base, parseUnary());
    }
    return base;
}

// primary := number | name | name '(' sum ')' | '(' sum ')'
int Expression::parsePrimary()
{
    skipBlanks();
    if (pos_ >= text_.size()) fail("unexpected end");
    const char c = text_[pos_];
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
        const char* begin = text_.c_str() + pos_;
        char* end = nullptr;
        const double value = std::strtod(begin, &end);
        if (end == begin) fail("bad number");
        pos_ += static_cast<std::size_t>(end - begin);
        return add(Op::number, -1, -1, value);
    }
    if (c == '(') {
        ++pos_;
        const int inner = parseSum();
        skipBlanks();
        if (pos_ >= text_.size() || text_[pos_] != ')') fail("missing ')'");
        ++pos_;
        return inner;
    }
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
        const std::size_t start = pos_;
        while (pos_ < text_.size() &&
               (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_'))
            ++pos_;
        const std::string name = text_.substr(start, pos_ - start);
        if (name == "t") {
            usesTime_ = true;
            return add(Op::time);
        }
        if (name == "pi") return add(Op::number, -1, -1, pi);
        Op op;
        if (name == "sin") op = Op::sin;
        else if (name == "cos") op = Op::cos;
        else if (name == "exp") op = Op::exp;
        else if (name == "sqrt") op = Op::sqrt;
        else if (name == "abs") op = Op::abs;
        else {
            pos_ = start;
            fail("unknown name '" + name + "'");
        }
        skipBlanks();
        if (pos_ >= text_.size() || text_[pos_] != '(') fail("'" + name + "' needs an argument in ( )");
        ++pos_;
        const int argument = parseSum();
        skipBlanks();
        if (pos_ >= text_.size() || text_[pos_] != ')') fail("missing ')'");
        ++pos_;
        return add(op, argument);
    }
    fail(std::string("unexpected '") + c + "'");
}

double Expression::evaluate(int n, double t) const
{
    const Node& node = nodes_[static_cast<std::size_t>(n)];
    switch (node.op) {
    case Op::number: return node.value;
    case Op::time: return t;
    case Op::add: return evaluate(node.a, t) + evaluate(node.b, t);
    case Op::subtract: return evaluate(node.a, t) - evaluate(node.b, t);
    case Op::multiply: return evaluate(node.a, t) * evaluate(node.b, t);
    case Op::divide: return evaluate(node.a, t) / evaluate(node.b, t);
    case Op::power: return std::pow(evaluate(node.a, t), evaluate(node.b, t));
    case Op::negate: return -evaluate(node.a, t);
    case Op::sin: return std::sin(evaluate(node.a, t));
    case Op::cos: return std::cos(evaluate(node.a, t));
    case Op::exp: return std::exp(evaluate(node.a, t));
    case Op::sqrt: return std::sqrt(evaluate(node.a, t));
    case Op::abs: return std::abs(evaluate(node.a, t));
    }
    return 0.0;
}

} // namespace gpic
