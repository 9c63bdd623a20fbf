#include "StepSolver.H"

#include "core/error.H"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

namespace gpic {

namespace {
//- "sigma11" ... by SymTensor component.
std::string componentName(int k)
{
    static const char* const names[6] = {"sigma11", "sigma22", "sigma33", "sigma12", "sigma23", "sigma13"};
    return names[k];
}
} // namespace

template <int D>
StepSolver<D>::StepSolver(double tolerance, int maxIterations)
    : tolerance_(tolerance), maxIterations_(maxIterations)
{}

template <int D> int StepSolver<D>::advance(MaterialPoint<D>& point, const StepControl<D>& control, double dt)
{
    std::vector<int> unknown;  // SymTensor components whose increment is sought
    for (int c = 0; c < Controlled<D>::n; ++c)
        if (control.stressControlled[c]) unknown.push_back(Controlled<D>::component()[c]);
    if (unknown.empty()) {
        point.apply(control.dEps, control.dOmega, dt);
        return 0;
    }
    const bool tied = control.eps33FollowsEps11;
    const int n = static_cast<int>(unknown.size());

    // A trial step from the start of the step with increments x for the unknowns.
    auto trial = [&](const Eigen::VectorXd& x, MaterialPoint<D>& result, Eigen::VectorXd& r) {
        SymTensor dEps = control.dEps;
        for (int i = 0; i < n; ++i) dEps[unknown[i]] = x[i];
        if (tied) dEps[ZZ] = dEps[XX];
        result = point;
        result.apply(dEps, control.dOmega, dt);
        r.resize(n);
        for (int i = 0; i < n; ++i) r[i] = result.sigma()[unknown[i]] - control.sigmaTarget[unknown[i]];
    };
    auto size = [](const Eigen::VectorXd& r) { return r.cwiseAbs().maxCoeff(); };

    const double scale = std::max({1.0, point.sigma().cwiseAbs().maxCoeff(),
                             control.sigmaTarget.cwiseAbs().maxCoeff()});
    const double allowed = tolerance_ * scale;

    Eigen::VectorXd x(n), r, rTry;
    for (int i = 0; i < n; ++i) x[i] = lastIncrement_[unknown[i]];
    MaterialPoint<D> current = point, attempt = point;
    trial(x, current, r);

    for (int iteration = 0; iteration <= maxIterations_; ++iteration) {
        if (!r.allFinite()) break;
        if (size(r) <= allowed) {
            point = current;
            for (int i = 0; i < n; ++i) lastIncrement_[unknown[i]] = x[i];
            return iteration;
        }
        if (iteration == maxIterations_) break;

        // Tangent by forward differences, perturbing each unknown by a small fraction of
        // the strain increments of the step.
        const double h = 1e-6 * std::max({control.dEps.cwiseAbs().maxCoeff(), x.cwiseAbs().maxCoeff(),
                                          1e-4});
        Eigen::MatrixXd J(n, n);
        for (int j = 0; j < n; ++j) {
            Eigen::VectorXd xj = x;
            xj[j] += h;
            trial(xj, attempt, rTry);
            J.col(j) = (rTry - r) / h;
        }
        const Eigen::FullPivLU<Eigen::MatrixXd> lu(J);
        if (!J.allFinite() || !lu.isInvertible()) {
            std::ostringstream msg;
            msg << "the stress cannot be controlled: " << componentName(unknown[0])
                << (n > 1 ? " and the other stress-controlled components do" : " does")
                << " not change with the strain (a perfectly plastic or failed state?)";
            throw RunError(msg.str());
        }
        const Eigen::VectorXd dx = -lu.solve(r);

        // Newton step, halved until it reduces the residual.
        double lambda = 1.0;
        Eigen::VectorXd xTry = x + dx;
        trial(xTry, attempt, rTry);
        for (int halving = 0; halving < 30 && !(rTry.allFinite() && size(rTry) < size(r)); ++halving) {
            lambda *= 0.5;
            xTry = x + lambda * dx;
            trial(xTry, attempt, rTry);
        }
        x = xTry;
        r = rTry;
        current = attempt;
    }

    int worst = 0;
    for (int i = 1; i < n; ++i)
        if (!(std::abs(r[i]) <= std::abs(r[worst]))) worst = i;
    std::ostringstream msg;
    msg << "the stress control did not converge in " << maxIterations_ << " iterations: "
        << componentName(unknown[worst]) << " misses its target " << control.sigmaTarget[unknown[worst]]
        << " Pa by " << r[worst] << " Pa (allowed " << allowed
        << " Pa; raise maxIterations or tolerance, or take more steps)";
    throw RunError(msg.str());
}

template class StepSolver<2>;
#if GPIC_WITH_3D
template class StepSolver<3>;
#endif

} // namespace gpic
