#include "bodies/VectorField.H"

#include "core/error.H"
#include "dictionary/Dictionary.H"
#include "dictionary/TokenConversion.H"
#include "dictionary/Tokenizer.H"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace gpic {

template <int D>
VectorField<D>::VectorField(const Dictionary& dict, const std::string& keyword, const Vector& deflt)
    : constant_(Vector::Zero())
{
    const Entry* e = dict.findEntry(keyword);
    const bool hasExpression =
        e && std::any_of(e->tokens.begin(), e->tokens.end(), [](const Token& t) { return t.kind == Token::Kind::string; });
    if (!hasExpression) {  // a vector as every getter reads it, unit brackets and all
        constant_ = dict.getOrDefault<Vector>(keyword, deflt);
        return;
    }
    const auto& t = e->tokens;
    auto expressions = std::make_shared<std::array<std::unique_ptr<Expression>, D>>();
    bool ok = t.size() == static_cast<std::size_t>(D + 2) && isPunct(t[0], '(') && isPunct(t[D + 1], ')');
    for (int a = 0; ok && a < D; ++a) {
        const Token& c = t[static_cast<std::size_t>(a + 1)];
        if (c.kind == Token::Kind::string)
            (*expressions)[static_cast<std::size_t>(a)] = std::make_unique<Expression>(
                c.text, c.file, c.line, D == 2 ? Expression::Variables::plane : Expression::Variables::space);
        else
            ok = c.kind == Token::Kind::word && convertTokens({c}, constant_[a]).empty();
    }
    if (!ok)
        dict.fail(keyword, "keyword '" + keyword + "' in dictionary " + dict.name() + ": expected " +
                               (D == 2 ? "(x y)" : "(x y z)") + " with numbers or \"expressions of " +
                               (D == 2 ? "x, y" : "x, y, z") + "\", found '" + writeTokens(t) + "'");
    expressions_ = std::move(expressions);
}

template <int D> typename VectorField<D>::Vector VectorField<D>::at(const Vector& x) const
{
    if (!expressions_) return constant_;
    Vector v = constant_;
    for (int a = 0; a < D; ++a) {
        const auto& f = (*expressions_)[static_cast<std::size_t>(a)];
        if (!f) continue;
        v[a] = f->at(0.0, x[0], x[1], D == 3 ? x[D - 1] : 0.0);
        if (!std::isfinite(v[a])) {
            std::ostringstream msg;
            msg << "expression \"" << f->text() << "\" is " << (std::isnan(v[a]) ? "nan" : v[a] > 0 ? "inf" : "-inf") << " at (" << x.transpose()
                << "): it must be finite wherever the body has particles";
            throw InputError(f->file(), f->line(), msg.str());
        }
    }
    return v;
}

template class VectorField<2>;
#if GPIC_WITH_3D
template class VectorField<3>;
#endif

} // namespace gpic
