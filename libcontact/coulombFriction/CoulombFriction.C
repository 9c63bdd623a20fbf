#include "coulombFriction/CoulombFriction.H"

#include <algorithm>
#include <cmath>

namespace gpic {

GPIC_REGISTER_DIMS(ContactLaw, CoulombFriction, "coulombFriction")

namespace {
const auto nonNegative = [](const double& m) { return m >= 0; };
} // namespace

template <int D>
CoulombFriction<D>::CoulombFriction(const Dictionary& dict, const std::vector<std::string>& bodyNames)
    : nBodies_(bodyNames.size()),
      mu_(nBodies_ * nBodies_, dict.getChecked<double>("mu", nonNegative, "mu >= 0"))
{
    const Dictionary* pairs = dict.subDictPtr("pairs");
    if (!pairs) return;
    std::string valid;
    for (const auto& b : bodyNames) valid += (valid.empty() ? "" : ", ") + b;
    for (const auto& key : pairs->keys()) {
        if (!pairs->isDict(key))
            pairs->fail(key, "'" + key + "' needs a pair sub-dictionary { bodies (a b); mu 0.2; }");
        const Dictionary& pair = pairs->subDict(key);
        const auto names = pair.getChecked<std::vector<std::string>>(
            "bodies", [](const std::vector<std::string>& v) { return v.size() == 2 && v[0] != v[1]; },
            "two different body names (a b)");
        std::size_t id[2];
        for (int i = 0; i < 2; ++i) {
            const auto it = std::find(bodyNames.begin(), bodyNames.end(), names[i]);
            if (it == bodyNames.end())
                pair.fail("bodies", "'" + names[i] + "' is not a body of the particles; valid choices: " + valid);
            id[i] = static_cast<std::size_t>(it - bodyNames.begin());
        }
        const double m = pair.getChecked<double>("mu", nonNegative, "mu >= 0");
        mu_[id[0] * nBodies_ + id[1]] = m;
        mu_[id[1] * nBodies_ + id[0]] = m;
    }
}

template <int D> double CoulombFriction<D>::mu(int a, int b) const
{
    return mu_[static_cast<std::size_t>(a) * nBodies_ + static_cast<std::size_t>(b)];
}

template <int D>
typename CoulombFriction<D>::Vector CoulombFriction<D>::correct(const Vector& v, const Vector& vRef, const Vector& n,
                                                                int body, int other) const
{
    const Vector vDiff = v - vRef;  // G.2.22
    if constexpr (D == 2) {
        const double approach = vDiff.x() * n.x() + vDiff.y() * n.y();  // normal approach speed
        if (approach <= 0.0) return v;                                  // separating (G.2.1)
        const double C = vDiff.x() * n.y() - vDiff.y() * n.x();         // G.2.23, sliding speed
        Vector corrected = v - approach * n;                            // G.2.3: stop the approach
        if (C != 0.0) {
            const double muEff = std::min(mu(body, other), std::abs(C) / approach);  // G.2.18
            const double s = C > 0.0 ? 1.0 : -1.0;
            corrected -= (approach * muEff * s) * Vector(n.y(), -n.x());  // G.2.26-27
        }
        return corrected;
    } else {
        const double approach = vDiff.dot(n);
        if (approach <= 0.0) return v;
        const Vector slide = vDiff - approach * n;  // the sliding velocity, across n
        const double C = slide.norm();
        Vector corrected = v - approach * n;
        if (C > 0.0) {
            const double muEff = std::min(mu(body, other), C / approach);
            corrected -= (approach * muEff / C) * slide;  // against the sliding, never past it
        }
        return corrected;
    }
}

template class CoulombFriction<2>;
#if GPIC_WITH_3D
template class CoulombFriction<3>;
#endif

} // namespace gpic
