#include "plasticity/PrincipalReturn.H"


#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace gpic {

namespace {

//- A candidate active set: its planes as a bit mask and as indices.
struct ActiveSet {
    unsigned mask = 0;
    int m = 0;
    int idx[3] = {0, 0, 0};
};

ActiveSet activeSet(unsigned mask)
{
    ActiveSet set;
    set.mask = mask;
    for (int i = 0; i < YieldPlanes::capacity; ++i)
        if (mask & (1u << i)) set.idx[set.m++] = i;
    return set;
}

//- Active sets of one to three planes, smaller sets first (built once, at load time).
const std::vector<ActiveSet> activeSets = [] {
    std::vector<ActiveSet> s;
    for (int size = 1; size <= 3; ++size)
        for (unsigned mask = 1; mask < (1u << YieldPlanes::capacity); ++mask)
            if (__builtin_popcount(mask) == size) s.push_back(activeSet(mask));
    return s;
}();

//- Solve the m x m system (m <= 3) A x = r by Cramer's rule; false when (near) singular.
bool solveSmall(int m, const double A[3][3], const double r[3], double x[3])
{
    if (m == 1) {
        if (!(std::abs(A[0][0]) > 0)) return false;
        x[0] = r[0] / A[0][0];
        return true;
    }
    double norm = 0;
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j) norm = std::max(norm, std::abs(A[i][j]));
    if (m == 2) {
        const double det = A[0][0] * A[1][1] - A[0][1] * A[1][0];
        if (!(std::abs(det) > 1e-12 * norm * norm)) return false;
        x[0] = (r[0] * A[1][1] - A[0][1] * r[1]) / det;
        x[1] = (A[0][0] * r[1] - r[0] * A[1][0]) / det;
        return true;
    }
    const double c00 = A[1][1] * A[2][2] - A[1][2] * A[2][1];
    const double c01 = A[1][2] * A[2][0] - A[1][0] * A[2][2];
    const double c02 = A[1][0] * A[2][1] - A[1][1] * A[2][0];
    const double det = A[0][0] * c00 + A[0][1] * c01 + A[0][2] * c02;
    if (!(std::abs(det) > 1e-12 * norm * norm * norm)) return false;
    // Cramer's rule: x_k = det(A with column k replaced by r) / det.
    x[0] = (r[0] * c00 + A[0][1] * (A[1][2] * r[2] - r[1] * A[2][2]) +
            A[0][2] * (r[1] * A[2][1] - A[1][1] * r[2])) / det;
    x[1] = (A[0][0] * (r[1] * A[2][2] - A[1][2] * r[2]) + r[0] * c01 +
            A[0][2] * (A[1][0] * r[2] - r[1] * A[2][0])) / det;
    x[2] = (A[0][0] * (A[1][1] * r[2] - r[1] * A[2][1]) + A[0][1] * (r[1] * A[2][0] - A[1][0] * r[2]) +
            r[0] * c02) / det;
    return true;
}

// Relative tolerance of the consistency test: well above round-off of a few operations on
// stresses of size `scale`, far below anything physical.
constexpr double tolerance = 1e-10;

} // namespace

PrincipalReturn::PrincipalReturn(double alpha1, double alpha2)
{
    D_ << alpha1, alpha2, alpha2, alpha2, alpha1, alpha2, alpha2, alpha2, alpha1;
}

PreparedPlanes PrincipalReturn::prepare(const YieldPlanes& planes) const
{
    PreparedPlanes p;
    p.planes = planes;
    for (int j = 0; j < planes.n; ++j) {
        p.Db[j] = D_ * planes.plane[j].b;
        p.DbNorm[j] = p.Db[j].norm();
        p.aNorm[j] = planes.plane[j].a.norm();
        p.kDistance[j] = std::abs(planes.plane[j].k) / p.aNorm[j];
    }
    for (int i = 0; i < planes.n; ++i)
        for (int j = 0; j < planes.n; ++j) p.M[i][j] = planes.plane[i].a.dot(p.Db[j]);
    return p;
}

PrincipalReturnResult PrincipalReturn::operator()(const Eigen::Vector3d& sigmaI,
                                                  const PreparedPlanes& prepared,
                                                  unsigned* activeSetHint) const
{
    constexpr int N = YieldPlanes::capacity;
    const YieldPlanes& planes = prepared.planes;
    const int n = planes.n;
    const auto& Db = prepared.Db;
    const auto& DbNorm = prepared.DbNorm;
    const auto& aNorm = prepared.aNorm;
    const auto& M = prepared.M;
    PrincipalReturnResult result;
    result.sigma = sigmaI;

    double fI[N];
    bool yielding = false;
    for (int i = 0; i < n; ++i) {
        fI[i] = planes.plane[i].a.dot(sigmaI) - planes.plane[i].k;
        yielding = yielding || fI[i] > 0;
    }
    if (!yielding) return result;
    double scale = sigmaI.cwiseAbs().maxCoeff();
    for (int i = 0; i < n; ++i) scale = std::max(scale, prepared.kDistance[i]);
    if (scale == 0) scale = 1;
    const double tol = tolerance * scale;

    double bestViolation = std::numeric_limits<double>::infinity();
    int bestIdx[3] = {0, 0, 0}, bestM = 0;
    unsigned bestMask = 0;
    double bestLambda[3] = {0, 0, 0};
    // Returns true when `set` is consistent (the search may stop).
    const auto trySet = [&](const ActiveSet& set) {
        if (set.mask >> n) return false;
        const int m = set.m;
        const int* idx = set.idx;
        double A[3][3], r[3] = {0, 0, 0}, lambda[3] = {0, 0, 0};
        for (int i = 0; i < m; ++i) {
            r[i] = fI[idx[i]];
            for (int j = 0; j < m; ++j) A[i][j] = M[idx[i]][idx[j]];
        }
        if (!solveSmall(m, A, r, lambda)) return false;  // planes meeting in a line or not at all

        // Consistency: multipliers >= 0, all yield values <= 0, principal order kept.
        double violation = 0;
        for (int j = 0; j < m; ++j) violation = std::max(violation, -lambda[j] * DbNorm[idx[j]]);
        if (violation >= bestViolation) return false;
        for (int i = 0; i < n; ++i) {
            double f = fI[i];
            for (int j = 0; j < m; ++j) f -= M[i][idx[j]] * lambda[j];
            violation = std::max(violation, f / aNorm[i]);
        }
        Eigen::Vector3d sigma = sigmaI;
        for (int j = 0; j < m; ++j) sigma -= lambda[j] * Db[idx[j]];
        violation = std::max({violation, sigma[0] - sigma[1], sigma[1] - sigma[2]});
        if (!(violation < bestViolation)) return false;

        bestViolation = violation;
        bestM = m;
        bestMask = set.mask;
        for (int j = 0; j < m; ++j) {
            bestIdx[j] = idx[j];
            bestLambda[j] = lambda[j];
        }
        result.sigma = sigma;
        return bestViolation <= tol;
    };
    // Neighbouring particles mostly return to the same region: the caller's set first.
    bool found = activeSetHint && *activeSetHint && trySet(activeSet(*activeSetHint));
    for (int k = 0; !found && k < planes.nLikely; ++k) found = trySet(activeSet(planes.likely[k]));
    for (std::size_t s = 0; !found && s < activeSets.size(); ++s) found = trySet(activeSets[s]);
    if (activeSetHint) *activeSetHint = bestMask;

    for (int j = 0; j < bestM; ++j) {
        // Every multiplier goes into the plastic strain, so that sigma = sigma_I - D dEpsP
        // holds to round-off; only those above round-off count as used.
        const YieldPlane& pj = planes.plane[bestIdx[j]];
        const bool used = bestLambda[j] * DbNorm[bestIdx[j]] > tol;
        if (pj.tension) {
            result.dEpsPTension += bestLambda[j] * pj.b;
            result.nTension += used;
        } else {
            result.dEpsPShear += bestLambda[j] * pj.b;
            result.nShear += used;
        }
    }
    return result;
}

} // namespace gpic
