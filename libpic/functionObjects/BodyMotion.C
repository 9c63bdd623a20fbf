#include "functionObjects/BodyMotion.H"

#include <algorithm>

namespace gpic {

GPIC_REGISTER(FunctionObject, BodyMotion, "bodyMotion")

BodyMotion::BodyMotion(const Dictionary& dict, const RunContext& context)
    : FunctionObject(dict, context)
{}

void BodyMotion::write(const MpmSolver<2>& solver, double time)
{
    const Particles<2>& p = solver.particles();
    const std::size_t nBodies = std::max<std::size_t>(context().bodyNames.size(), 1);
    std::vector<double> mass(nBodies, 0), kinetic(nBodies, 0), strain(nBodies, 0);
    std::vector<Vector2> moment(nBodies, Vector2::Zero()), momentum(nBodies, Vector2::Zero());
    for (std::size_t q = 0; q < p.size(); ++q) {
        const auto b = static_cast<std::size_t>(std::clamp<int>(p.body[q], 0, int(nBodies) - 1));
        mass[b] += p.m[q];
        moment[b] += p.m[q] * p.x[q];
        momentum[b] += p.m[q] * p.v[q];
        kinetic[b] += p.kineticEnergy(q);  // APIC: with the part C_p carries
        strain[b] += p.work[q];
    }
    std::ofstream& os = file("bodyMotion.dat");
    if (os.tellp() == 0) {
        os << "# per body b: centre of mass, its velocity, momentum [kg m/s per m], kinetic and "
              "strain energy [J per m]\n# time";
        for (std::size_t b = 0; b < nBodies; ++b) {
            const std::string n = b < context().bodyNames.size() ? context().bodyNames[b] : "all";
            for (const char* c : {"x", "y", "vx", "vy", "px", "py", "Ek", "Es"})
                os << ' ' << n << ':' << c;
        }
        os << " Ek Es E\n";
    }
    double Ek = 0, Es = 0;
    os << time;
    for (std::size_t b = 0; b < nBodies; ++b) {
        const Vector2 c = mass[b] > 0 ? Vector2(moment[b] / mass[b]) : Vector2::Zero();
        const Vector2 vc = mass[b] > 0 ? Vector2(momentum[b] / mass[b]) : Vector2::Zero();
        os << ' ' << c.x() << ' ' << c.y() << ' ' << vc.x() << ' ' << vc.y() << ' '
           << momentum[b].x() << ' ' << momentum[b].y() << ' ' << kinetic[b] << ' ' << strain[b];
        Ek += kinetic[b];
        Es += strain[b];
    }
    os << ' ' << Ek << ' ' << Es << ' ' << Ek + Es << '\n';
}

} // namespace gpic
