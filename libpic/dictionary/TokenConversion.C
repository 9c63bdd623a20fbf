#include "dictionary/TokenConversion.H"

#include "dictionary/Tokenizer.H"

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>

namespace gpic {

namespace {

//- A run of tokens [begin, end).
struct Span {
    const Token* begin;
    const Token* end;
    std::size_t size() const { return static_cast<std::size_t>(end - begin); }
};

std::vector<Token> withoutUnits(const std::vector<Token>& tokens)
{
    std::vector<Token> out;
    int depth = 0;
    for (const Token& t : tokens) {
        if (isPunct(t, '['))
            ++depth;
        else if (isPunct(t, ']'))
            --depth;
        else if (depth == 0)
            out.push_back(t);
    }
    return out;
}

//- The elements of one balanced list `( a "b" (c d) )`: single tokens or nested lists.
bool listElements(Span s, std::vector<Span>& elements)
{
    if (s.size() < 2 || !isPunct(*s.begin, '(') || !isPunct(*(s.end - 1), ')')) return false;
    int depth = 0;
    const Token* start = nullptr;
    for (const Token* p = s.begin + 1; p != s.end - 1; ++p) {
        if (isPunct(*p, '(')) {
            if (depth++ == 0) start = p;
        } else if (isPunct(*p, ')')) {
            if (--depth < 0) return false;  // `(1) (2)` is two lists, not one
            if (depth == 0) elements.push_back({start, p + 1});
        } else if (depth == 0) {
            if (p->kind == Token::Kind::punctuation) return false;
            elements.push_back({p, p + 1});
        }
    }
    return depth == 0;
}

//- Reads spans as values; remembers a nonzero third vector component for a clearer message.
struct Reader {
    bool outOfPlane = false;

    static bool single(Span s) { return s.size() == 1 && s.begin->kind == Token::Kind::word; }

    bool read(Span s, double& x)
    {
        if (!single(s)) return false;
        const char* text = s.begin->text.c_str();
        char* end = nullptr;
        x = std::strtod(text, &end);
        // inf, nan and overflow are no input: `E inf` would pass every check of E > 0.
        return end != text && *end == '\0' && std::isfinite(x);
    }
    bool read(Span s, long& x)
    {
        if (!single(s)) return false;
        const char* text = s.begin->text.c_str();
        char* end = nullptr;
        errno = 0;
        x = std::strtol(text, &end, 10);
        return end != text && *end == '\0' && errno != ERANGE;
    }
    bool read(Span s, int& x)
    {
        long wide = 0;
        if (!read(s, wide) || wide < INT_MIN || wide > INT_MAX) return false;
        x = static_cast<int>(wide);
        return true;
    }
    bool read(Span s, bool& x)
    {
        if (!single(s)) return false;
        const std::string& w = s.begin->text;
        x = w == "yes" || w == "on" || w == "true";
        return x || w == "no" || w == "off" || w == "false";
    }
    bool read(Span s, std::string& x)
    {
        if (s.size() != 1 || s.begin->kind == Token::Kind::punctuation) return false;
        x = s.begin->text;
        return true;
    }
    //- A plane vector: (x y), or (x y 0) as a 3D tool may write it.
    bool read(Span s, Eigen::Vector2d& v)
    {
        std::vector<Span> e;
        double z = 0;
        if (!listElements(s, e) || e.size() < 2 || e.size() > 3) return false;
        if (!read(e[0], v.x()) || !read(e[1], v.y())) return false;
        if (e.size() == 3 && (!read(e[2], z) || z != 0)) {
            outOfPlane = outOfPlane || z != 0;
            return false;
        }
        return true;
    }
    bool read(Span s, Eigen::Vector3d& v)
    {
        std::vector<Span> e;
        return listElements(s, e) && e.size() == 3 && read(e[0], v.x()) && read(e[1], v.y()) &&
               read(e[2], v.z());
    }
    template <class T> bool read(Span s, std::vector<T>& list)
    {
        std::vector<Span> e;
        if (!listElements(s, e)) return false;
        list.resize(e.size());
        for (std::size_t i = 0; i < e.size(); ++i) {
            T item{};
            if (!read(e[i], item)) return false;
            list[i] = item;
        }
        return true;
    }
};

//- "found 'abc'", plus a hint when the value runs over lines outside brackets: then the
//  `;` of the entry's first line was most likely forgotten.
std::string found(const std::vector<Token>& tokens)
{
    if (tokens.empty()) return "found nothing";
    std::string text = "found '" + writeTokens(tokens) + "'";
    int depth = 0;
    int lastLine = tokens.front().line;
    for (const Token& t : tokens) {
        if (depth == 0 && t.line > lastLine && lastLine > 0)
            return text + " (missing ';' at the end of line " + std::to_string(lastLine) + "?)";
        if (isPunct(t, '(') || isPunct(t, '[')) ++depth;
        if (isPunct(t, ')') || isPunct(t, ']')) --depth;
        if (depth == 0) lastLine = t.line;
    }
    return text;
}

template <class T> std::string convert(const std::vector<Token>& tokens, T& value)
{
    const std::vector<Token> clean = withoutUnits(tokens);
    Reader reader;
    if (reader.read(Span{clean.data(), clean.data() + clean.size()}, value)) return "";
    if (reader.outOfPlane)
        return "the third component must be 0 (plane strain: write (x y) or (x y 0)), " +
               found(tokens);
    return std::string("expected ") + expectedForm(&value) + ", " + found(tokens);
}

} // namespace

// clang-format off
using Tokens = std::vector<Token>;
using Table = std::vector<std::vector<double>>;
std::string convertTokens(const Tokens& t, double& v) { return convert(t, v); }
std::string convertTokens(const Tokens& t, int& v) { return convert(t, v); }
std::string convertTokens(const Tokens& t, long& v) { return convert(t, v); }
std::string convertTokens(const Tokens& t, bool& v) { return convert(t, v); }
std::string convertTokens(const Tokens& t, std::string& v) { return convert(t, v); }
std::string convertTokens(const Tokens& t, Eigen::Vector2d& v) { return convert(t, v); }
std::string convertTokens(const Tokens& t, Eigen::Vector3d& v) { return convert(t, v); }
std::string convertTokens(const Tokens& t, std::vector<double>& v) { return convert(t, v); }
std::string convertTokens(const Tokens& t, std::vector<int>& v) { return convert(t, v); }
std::string convertTokens(const Tokens& t, std::vector<std::string>& v) { return convert(t, v); }
std::string convertTokens(const Tokens& t, std::vector<Eigen::Vector2d>& v) { return convert(t, v); }
std::string convertTokens(const Tokens& t, std::vector<Eigen::Vector3d>& v) { return convert(t, v); }
std::string convertTokens(const Tokens& t, Table& v) { return convert(t, v); }

const char* expectedForm(const double*) { return "a number"; }
const char* expectedForm(const int*) { return "an integer"; }
const char* expectedForm(const long*) { return "an integer"; }
const char* expectedForm(const bool*) { return "a switch (yes/no/on/off/true/false)"; }
const char* expectedForm(const std::string*) { return "a single word or \"string\""; }
const char* expectedForm(const Eigen::Vector2d*) { return "a vector (x y)"; }
const char* expectedForm(const Eigen::Vector3d*) { return "a vector (x y z)"; }
const char* expectedForm(const std::vector<double>*) { return "a list of numbers (a b ...)"; }
const char* expectedForm(const std::vector<int>*) { return "a list of integers (i j ...)"; }
const char* expectedForm(const std::vector<std::string>*) { return "a list of words (a b ...)"; }
const char* expectedForm(const std::vector<Eigen::Vector2d>*) { return "a list of vectors ((x y) ...)"; }
const char* expectedForm(const std::vector<Eigen::Vector3d>*) { return "a list of vectors ((x y z) ...)"; }
const char* expectedForm(const Table*) { return "a table ((x0 y0) (x1 y1) ...)"; }
// clang-format on

} // namespace gpic
