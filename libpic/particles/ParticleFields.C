#include "particles/ParticleFields.H"

#include <cmath>

namespace gpic {

namespace {

using G = FieldGroup;
using R = FieldRole;

template <int D> void displacement(const Particles<D>& p, std::size_t q, double* out)
{
    const typename Space<D>::Vector u = p.x[q] - p.x0[q];
    out[0] = u.x(); out[1] = u.y(); out[2] = D == 3 ? u[D - 1] : 0.0;
}

//- Mean pressure -tr(sigma)/3, compression positive.
template <int D> void pressure(const Particles<D>& p, std::size_t q, double* out)
{
    const typename Space<D>::SymTensor& s = p.sigma[q];
    out[0] = -(s[XX] + s[YY] + s[ZZ]) / 3.0;
}

//- sqrt(3 J2) of the symmetric stress.
template <int D> void vonMisesStress(const Particles<D>& p, std::size_t q, double* out)
{
    const typename Space<D>::SymTensor& s = p.sigma[q];
    const double mean = (s[XX] + s[YY] + s[ZZ]) / 3.0;
    const double d1 = s[XX] - mean, d2 = s[YY] - mean, d3 = s[ZZ] - mean;
    double J2 = 0.5 * (d1 * d1 + d2 * d2 + d3 * d3) + s[XY] * s[XY];
    for (int c = Space<2>::nSym; c < Space<D>::nSym; ++c) J2 += s[c] * s[c];
    out[0] = std::sqrt(3.0 * J2);
}

//- The radius of the disk of the particle's current area (its volume per unit thickness;
//  in 3D of the sphere of its volume), a one-component size that ParaView's glyphs scale by
//  (halfSize does not follow the deformation).
template <int D> void radius(const Particles<D>& p, std::size_t q, double* out)
{
    constexpr double pi = 3.14159265358979323846;
    out[0] = D == 2 ? std::sqrt(p.V[q] / pi) : std::cbrt(0.75 * p.V[q] / pi);
}

} // namespace

template <int D> const std::vector<ParticleField<D>>& particleFields()
{
    using P = Particles<D>;
    using A = FieldArray<D>;
    static const std::vector<ParticleField<D>> table = [] {
        std::vector<ParticleField<D>> t{
            {"id", G::core, R::state, 1, [](P& p) -> A { return &p.id; }},
            {"body", G::core, R::state, 1, [](P& p) -> A { return &p.body; }},
            {"material", G::core, R::state, 1, [](P& p) -> A { return &p.material; }},
            {"", G::core, R::state, 3, [](P& p) -> A { return &p.x; }, "points"},
            {"velocity", G::core, R::state, 3, [](P& p) -> A { return &p.v; }},
            {"displacement", G::core, R::derived, 3, nullptr, nullptr, 0, displacement<D>},
            {"initialPosition", G::core, R::state, 3, [](P& p) -> A { return &p.x0; }},
            {"mass", G::core, R::state, 1, [](P& p) -> A { return &p.m; }},
            {"volume", G::core, R::state, 1, [](P& p) -> A { return &p.V; }},
            {"radius", G::core, R::derived, 1, nullptr, nullptr, 0, radius<D>},
            {"work", G::core, R::state, 1, [](P& p) -> A { return &p.work; }},
            {"halfSize", G::core, R::state, D == 2 ? 2 : 3, [](P& p) -> A { return &p.halfSize; }},
            {"stress", G::core, R::state, 9, [](P& p) -> A { return &p.sigma; }},
            {"strain", G::core, R::state, 9, [](P& p) -> A { return &p.eps; }},
            {"plasticStrain", G::plasticStrain, R::state, 9, [](P& p) -> A { return &p.epsP; }},
            {"pressure", G::core, R::derived, 1, nullptr, nullptr, 0, pressure<D>},
            {"vonMisesStress", G::core, R::derived, 1, nullptr, nullptr, 0, vonMisesStress<D>},
            {"", G::core, R::scratch, 0, [](P& p) -> A { return &p.dEps; }},
            {"", G::core, R::scratch, 0, [](P& p) -> A { return &p.dOmega; }},
            {"affineVelocity", G::affine, R::state, 9, [](P& p) -> A { return &p.affine; }},
            {"affineKineticEnergy", G::affine, R::state, 1, [](P& p) -> A { return &p.affineEnergy; }},
        };
        if constexpr (D == 2) {
            const std::vector<ParticleField<D>> polar{
                {"microRotation", G::polar, R::state, 1, [](P& p) -> A { return &p.polar.w; }},
                {"microRotationRate", G::polar, R::state, 1, [](P& p) -> A { return &p.polar.omega; }},
                // A Cosserat stress is not symmetric: sigma21 is the yx entry of `stress`.
                {"", G::polar, R::state, 1, [](P& p) -> A { return &p.polar.sigma21; }, "stress", 3},
                {"coupleStress", G::polar, R::state, 3, [](P& p) -> A { return &p.polar.mu; }},
                {"curvature", G::polar, R::state, 3, [](P& p) -> A { return &p.polar.kappa; }},
                {"", G::polar, R::scratch, 0, [](P& p) -> A { return &p.polar.dRotation; }},
                {"", G::polar, R::scratch, 0, [](P& p) -> A { return &p.polar.dKappa; }},
            };
            t.insert(t.end(), polar.begin(), polar.end());
        }
        return t;
    }();
    return table;
}

template const std::vector<ParticleField<2>>& particleFields<2>();
#if GPIC_WITH_3D
template const std::vector<ParticleField<3>>& particleFields<3>();
#endif

} // namespace gpic
