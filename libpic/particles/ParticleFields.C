#include "particles/ParticleFields.H"

#include <cmath>

namespace gpic {

namespace {

using G = FieldGroup;
using R = FieldRole;

void displacement(const Particles& p, std::size_t q, double* out)
{
    const Vector2 u = p.x[q] - p.x0[q];
    out[0] = u.x(); out[1] = u.y(); out[2] = 0.0;
}

//- Mean pressure -tr(sigma)/3, compression positive.
void pressure(const Particles& p, std::size_t q, double* out)
{
    const SymTensor& s = p.sigma[q];
    out[0] = -(s[XX] + s[YY] + s[ZZ]) / 3.0;
}

//- sqrt(3 J2) of the symmetric stress.
void vonMisesStress(const Particles& p, std::size_t q, double* out)
{
    const SymTensor& s = p.sigma[q];
    const double mean = (s[XX] + s[YY] + s[ZZ]) / 3.0;
    const double d1 = s[XX] - mean, d2 = s[YY] - mean, d3 = s[ZZ] - mean;
    const double J2 = 0.5 * (d1 * d1 + d2 * d2 + d3 * d3) + s[XY] * s[XY];
    out[0] = std::sqrt(3.0 * J2);
}

//- The radius of the disk of the particle's current area (its volume per unit thickness),
//  a one-component size that ParaView's glyphs scale by (halfSize does not follow the
//  deformation).
void radius(const Particles& p, std::size_t q, double* out)
{
    constexpr double pi = 3.14159265358979323846;
    out[0] = std::sqrt(p.V[q] / pi);
}

} // namespace

const std::vector<ParticleField>& particleFields()
{
    static const std::vector<ParticleField> table{
        {"id", G::core, R::state, 1, [](Particles& p) -> FieldArray { return &p.id; }},
        {"body", G::core, R::state, 1, [](Particles& p) -> FieldArray { return &p.body; }},
        {"material", G::core, R::state, 1, [](Particles& p) -> FieldArray { return &p.material; }},
        {"", G::core, R::state, 3, [](Particles& p) -> FieldArray { return &p.x; }, "points"},
        {"velocity", G::core, R::state, 3, [](Particles& p) -> FieldArray { return &p.v; }},
        {"displacement", G::core, R::derived, 3, nullptr, nullptr, 0, displacement},
        {"initialPosition", G::core, R::state, 3, [](Particles& p) -> FieldArray { return &p.x0; }},
        {"mass", G::core, R::state, 1, [](Particles& p) -> FieldArray { return &p.m; }},
        {"volume", G::core, R::state, 1, [](Particles& p) -> FieldArray { return &p.V; }},
        {"radius", G::core, R::derived, 1, nullptr, nullptr, 0, radius},
        {"work", G::core, R::state, 1, [](Particles& p) -> FieldArray { return &p.work; }},
        {"halfSize", G::core, R::state, 2, [](Particles& p) -> FieldArray { return &p.halfSize; }},
        {"stress", G::core, R::state, 9, [](Particles& p) -> FieldArray { return &p.sigma; }},
        {"strain", G::core, R::state, 9, [](Particles& p) -> FieldArray { return &p.eps; }},
        {"plasticStrain", G::plasticStrain, R::state, 9, [](Particles& p) -> FieldArray { return &p.epsP; }},
        {"pressure", G::core, R::derived, 1, nullptr, nullptr, 0, pressure},
        {"vonMisesStress", G::core, R::derived, 1, nullptr, nullptr, 0, vonMisesStress},
        {"", G::core, R::scratch, 0, [](Particles& p) -> FieldArray { return &p.dEps; }},
        {"", G::core, R::scratch, 0, [](Particles& p) -> FieldArray { return &p.dOmega; }},
        {"affineVelocity", G::affine, R::state, 9, [](Particles& p) -> FieldArray { return &p.affine; }},
        {"affineKineticEnergy", G::affine, R::state, 1, [](Particles& p) -> FieldArray { return &p.affineEnergy; }},
        {"microRotation", G::polar, R::state, 1, [](Particles& p) -> FieldArray { return &p.polar.w; }},
        {"microRotationRate", G::polar, R::state, 1, [](Particles& p) -> FieldArray { return &p.polar.omega; }},
        // A Cosserat stress is not symmetric: sigma21 is the yx entry of `stress`.
        {"", G::polar, R::state, 1, [](Particles& p) -> FieldArray { return &p.polar.sigma21; }, "stress", 3},
        {"coupleStress", G::polar, R::state, 3, [](Particles& p) -> FieldArray { return &p.polar.mu; }},
        {"curvature", G::polar, R::state, 3, [](Particles& p) -> FieldArray { return &p.polar.kappa; }},
        {"", G::polar, R::scratch, 0, [](Particles& p) -> FieldArray { return &p.polar.dRotation; }},
        {"", G::polar, R::scratch, 0, [](Particles& p) -> FieldArray { return &p.polar.dKappa; }},
    };
    return table;
}

FieldArray fieldArray(const ParticleField& f, const Particles& p)
{
    // The table's accessors name members; reading through them does not modify p.
    return f.array(const_cast<Particles&>(p));
}

} // namespace gpic
