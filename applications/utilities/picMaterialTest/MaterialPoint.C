#include "MaterialPoint.H"

#include <cmath>

namespace gpic {

MaterialPoint::MaterialPoint(const Material<2>& material, const SymTensor& sigma0)
    : material_(&material)
{
    material.declareFields(particles_);
    particles_.add(Vector2::Zero(), material.rho(), 1.0, Vector2::Constant(0.5), 0, 0);
    particles_.sigma[0] = sigma0;
    if (material.needsRotation()) {  // polar: the micro-rotation follows the continuum (no
        particles_.carry(FieldGroup::polar);  // relative rotation, no curvature), sigma21 = sigma12
        particles_.polar.sigma21[0] = sigma0[XY];
    }
}

void MaterialPoint::apply(const SymTensor& dEps, double dOmega, double dt)
{
    Particles<2>& p = particles_;
    p.dEps[0] = dEps;  // de33: zero in plane strain, the hoop strain of an axisymmetric ring
    p.dOmega[0] = dOmega;
    p.eps[0] += p.dEps[0];
    // Volume follows the deformation as in the solver: det(I + dt L), with
    // dt L12 = dEps12 + dOmega and dt L21 = dEps12 - dOmega.
    p.V[0] *= (1.0 + dEps[XX]) * (1.0 + dEps[YY]) - (dEps[XY] + dOmega) * (dEps[XY] - dOmega);
    if (dEps[ZZ] != 0.0) p.V[0] *= 1.0 + dEps[ZZ];
    material_->updateStress(p, {0, 1, 0}, dt);
}

double MaterialPoint::p() const
{
    const SymTensor& s = sigma();
    return 0.0 - (s[XX] + s[YY] + s[ZZ]) / 3.0;  // 0.0 - : no "-0" in the output
}

double MaterialPoint::q() const
{
    // q = sqrt(3/2 s:s) with the deviator s; the shear pair counts twice.
    const SymTensor& s = sigma();
    const double mean = -p();
    const double sxx = s[XX] - mean, syy = s[YY] - mean, szz = s[ZZ] - mean;
    return std::sqrt(1.5 * (sxx * sxx + syy * syy + szz * szz + 2.0 * s[XY] * s[XY]));
}

std::vector<double> MaterialPoint::history() const
{
    std::vector<double> values;
    for (const auto& name : particles_.historyNames()) values.push_back(particles_.history(name)[0]);
    return values;
}

} // namespace gpic
