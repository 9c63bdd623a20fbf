#include "functionObjects/BodyMotion.H"

#include <algorithm>
#include <vector>

namespace gpic {

GPIC_REGISTER_DIMS(FunctionObject, BodyMotion, "bodyMotion")

template <int D>
BodyMotion<D>::BodyMotion(const Dictionary& dict, const RunContext& context)
    : FunctionObject<D>(dict, context)
{}

template <int D>
void BodyMotion<D>::write(const MpmSolver<D>& solver, double time)
{
    const Particles<D>& p = solver.particles();
    const std::size_t nBodies = std::max<std::size_t>(context().bodyNames.size(), 1);
    std::vector<double> mass(nBodies, 0), kinetic(nBodies, 0), strain(nBodies, 0);
    std::vector<Vector> moment(nBodies, Vector::Zero()), momentum(nBodies, Vector::Zero());
    for (std::size_t q = 0; q < p.size(); ++q) {
        const auto b = static_cast<std::size_t>(std::clamp<int>(p.body[q], 0, int(nBodies) - 1));
        mass[b] += p.m[q];
        moment[b] += p.m[q] * p.x[q];
        momentum[b] += p.m[q] * p.v[q];
        kinetic[b] += p.kineticEnergy(q);  // APIC: with the part C_p carries
        strain[b] += p.work[q];
    }
    // A parallel run: every rank's particles, rank 0 writes.
    std::vector<double> sums;
    for (std::size_t b = 0; b < nBodies; ++b) {
        sums.insert(sums.end(), {mass[b], kinetic[b], strain[b]});
        for (int a = 0; a < D; ++a) sums.insert(sums.end(), {moment[b][a], momentum[b][a]});
    }
    solver.sumOverRanks(sums);
    for (std::size_t b = 0, k = 0; b < nBodies; ++b) {
        mass[b] = sums[k++], kinetic[b] = sums[k++], strain[b] = sums[k++];
        for (int a = 0; a < D; ++a) moment[b][a] = sums[k++], momentum[b][a] = sums[k++];
    }
    if (!solver.writesFiles()) return;
    std::ofstream& os = file("bodyMotion.dat");
    if (os.tellp() == 0) {
        if constexpr (D == 2)
            os << "# per body b: centre of mass, its velocity, momentum [kg m/s per m], kinetic and "
                  "strain energy [J per m]\n# time";
        else
            os << "# per body b: centre of mass, its velocity, momentum [kg m/s], kinetic and strain energy [J]\n# time";
        const char* const plane[] = {"x", "y", "vx", "vy", "px", "py", "Ek", "Es"};
        const char* const solid[] = {"x", "y", "z", "vx", "vy", "vz", "px", "py", "pz", "Ek", "Es"};
        for (std::size_t b = 0; b < nBodies; ++b) {
            const std::string n = b < context().bodyNames.size() ? context().bodyNames[b] : "all";
            for (const char* c : D == 2 ? std::vector<const char*>(plane, plane + 8) : std::vector<const char*>(solid, solid + 11))
                os << ' ' << n << ':' << c;
        }
        os << " Ek Es E\n";
    }
    double Ek = 0, Es = 0;
    os << time;
    for (std::size_t b = 0; b < nBodies; ++b) {
        const Vector c = mass[b] > 0 ? Vector(moment[b] / mass[b]) : Vector::Zero();
        const Vector vc = mass[b] > 0 ? Vector(momentum[b] / mass[b]) : Vector::Zero();
        for (const Vector* v : std::initializer_list<const Vector*>{&c, &vc, &momentum[b]})
            for (int a = 0; a < D; ++a) os << ' ' << (*v)[a];
        os << ' ' << kinetic[b] << ' ' << strain[b];
        Ek += kinetic[b];
        Es += strain[b];
    }
    os << ' ' << Ek << ' ' << Es << ' ' << Ek + Es << '\n';
}

template class BodyMotion<2>;
#if GPIC_WITH_3D
template class BodyMotion<3>;
#endif

} // namespace gpic
