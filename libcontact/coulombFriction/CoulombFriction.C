#include "coulombFriction/CoulombFriction.H"

#include <algorithm>
#include <cmath>

namespace gpic {

GPIC_REGISTER(ContactLaw<2>, CoulombFriction, "coulombFriction")

namespace {
const auto nonNegative = [](const double& m) { return m >= 0; };
} // namespace

CoulombFriction::CoulombFriction(const Dictionary& dict, const std::vector<std::string>& bodyNames)
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

double CoulombFriction::mu(int a, int b) const
{
    return mu_[static_cast<std::size_t>(a) * nBodies_ + static_cast<std::size_t>(b)];
}

Vector2 CoulombFriction::correct(const Vector2& v, const Vector2& vRef, const Vector2& n, int body,
                                 int other) const
{
    const Vector2 vDiff = v - vRef;                              // G.2.22
    const double D = vDiff.x() * n.x() + vDiff.y() * n.y();      // normal approach speed
    if (D <= 0.0) return v;                                      // separating (G.2.1)
    const double C = vDiff.x() * n.y() - vDiff.y() * n.x();      // G.2.23, sliding speed
    Vector2 corrected = v - D * n;                               // G.2.3: stop the approach
    if (C != 0.0) {
        const double muEff = std::min(mu(body, other), std::abs(C) / D);  // G.2.18
        const double s = C > 0.0 ? 1.0 : -1.0;
        corrected -= (D * muEff * s) * Vector2(n.y(), -n.x());  // G.2.26-27
    }
    return corrected;
}

} // namespace gpic
