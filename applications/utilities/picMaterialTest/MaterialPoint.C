#include "MaterialPoint.H"

#include <Eigen/LU>

#include <cmath>

namespace gpic {

template <int D>
MaterialPoint<D>::MaterialPoint(const Material<D>& material, const SymTensor& sigma0)
    : material_(&material)
{
    using Vector = typename Space<D>::Vector;
    material.declareFields(particles_);
    particles_.add(Vector::Zero(), material.rho(), 1.0, Vector::Constant(0.5), 0, 0);
    particles_.sigma[0] = sigma0;
    if constexpr (D == 2)
        if (material.needsRotation()) {  // polar: the micro-rotation follows the continuum (no
            particles_.carry(FieldGroup::polar);  // relative rotation, no curvature), sigma21 = sigma12
            particles_.polar.sigma21[0] = sigma0[XY];
        }
}

template <int D>
void MaterialPoint<D>::apply(const SymTensor& dEps, const typename Space<D>::Spin& dOmega, double dt)
{
    Particles<D>& p = particles_;
    p.dEps[0] = dEps;  // de33 in the plane: zero in plane strain, the hoop strain of an axisymmetric ring
    p.dOmega[0] = dOmega;
    p.eps[0] += p.dEps[0];
    // Volume follows the deformation as in the solver: det(I + dt L), with dt L the strain
    // increment plus the spin, dt L12 = dEps12 + w12 and dt L21 = dEps12 - w12.
    if constexpr (D == 2) {
        p.V[0] *= (1.0 + dEps[XX]) * (1.0 + dEps[YY]) - (dEps[XY] + dOmega) * (dEps[XY] - dOmega);
        if (dEps[ZZ] != 0.0) p.V[0] *= 1.0 + dEps[ZZ];
    } else {
        Eigen::Matrix3d F;  // I + dt L; the spin stored as (w12 w23 w13)
        F << 1.0 + dEps[XX], dEps[XY] + dOmega[0], dEps[XZ] + dOmega[2],  //
            dEps[XY] - dOmega[0], 1.0 + dEps[YY], dEps[YZ] + dOmega[1],  //
            dEps[XZ] - dOmega[2], dEps[YZ] - dOmega[1], 1.0 + dEps[ZZ];
        p.V[0] *= F.determinant();
    }
    material_->updateStress(p, {0, 1, 0}, dt);
}

template <int D> double MaterialPoint<D>::p() const
{
    const SymTensor& s = sigma();
    return 0.0 - (s[XX] + s[YY] + s[ZZ]) / 3.0;  // 0.0 - : no "-0" in the output
}

template <int D> double MaterialPoint<D>::q() const
{
    // q = sqrt(3/2 s:s) with the deviator s; each shear pair counts twice.
    const SymTensor& s = sigma();
    const double mean = -p();
    const double sxx = s[XX] - mean, syy = s[YY] - mean, szz = s[ZZ] - mean;
    if constexpr (D == 2) return std::sqrt(1.5 * (sxx * sxx + syy * syy + szz * szz + 2.0 * s[XY] * s[XY]));
    const double shear = s[XY] * s[XY] + s[YZ] * s[YZ] + s[XZ] * s[XZ];
    return std::sqrt(1.5 * (sxx * sxx + syy * syy + szz * szz + 2.0 * shear));
}

template <int D> std::vector<double> MaterialPoint<D>::history() const
{
    std::vector<double> values;
    for (const auto& name : particles_.historyNames()) values.push_back(particles_.history(name)[0]);
    return values;
}

template class MaterialPoint<2>;
#if GPIC_WITH_3D
template class MaterialPoint<3>;
#endif

} // namespace gpic
