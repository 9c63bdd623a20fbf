// A small, independent 3D MPM (USL, trilinear cells, lumped mass, FLIP update, linear
// elasticity with the stress turned by the step's spin, R = exp(W) with W = dt (L - L^T)/2,
// and V <- det(I + dt L) V), written from the seed's eqs. 2.4.1-2.4.8 and H.2.1 taken to
// three dimensions, against which the engine is compared on two elastic spheres that meet
// (a 3D twoDisks, run from its case files through picInit and picSolver). As
// referenceMpmTest is for the plane engine, it guards the 3D engine's structure (weights,
// strips, verbs, the Jaumann rotation) against changes that alter results.
#include "support/CaseRunner.H"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

using namespace gpic::test;

namespace {

struct ReferenceMpm3D {
    // Grid: n[0] x n[1] x n[2] cells of size h from the origin; free sides.
    std::array<int, 3> n;
    double h;
    double E, nu;
    std::vector<Eigen::Vector3d> x, v;
    std::vector<double> m, V;
    std::vector<Eigen::Matrix3d> sigma;

    int node(int i, int j, int k) const { return i + (n[0] + 1) * (j + (n[1] + 1) * k); }

    void step(double dt)
    {
        const int nn = (n[0] + 1) * (n[1] + 1) * (n[2] + 1);
        std::vector<double> mass(nn, 0.0);
        std::vector<Eigen::Vector3d> p(nn, Eigen::Vector3d::Zero()), f(nn, Eigen::Vector3d::Zero());
        const std::size_t np = x.size();
        std::vector<std::array<int, 8>> nodes(np);
        std::vector<std::array<double, 8>> N(np);
        std::vector<std::array<Eigen::Vector3d, 8>> dN(np);
        for (std::size_t q = 0; q < np; ++q) {
            int c[3];
            double xi[3];
            for (int a = 0; a < 3; ++a) {
                c[a] = std::min(n[a] - 1, int(std::floor(x[q][a] / h)));
                xi[a] = x[q][a] / h - c[a];
            }
            for (int corner = 0; corner < 8; ++corner) {
                const int o[3] = {corner & 1, (corner >> 1) & 1, (corner >> 2) & 1};
                double w[3], g[3];
                for (int a = 0; a < 3; ++a) {
                    w[a] = o[a] ? xi[a] : 1 - xi[a];
                    g[a] = (o[a] ? 1.0 : -1.0) / h;
                }
                nodes[q][corner] = node(c[0] + o[0], c[1] + o[1], c[2] + o[2]);
                N[q][corner] = w[0] * w[1] * w[2];
                dN[q][corner] = Eigen::Vector3d(g[0] * w[1] * w[2], w[0] * g[1] * w[2], w[0] * w[1] * g[2]);
                const int i = nodes[q][corner];
                mass[i] += N[q][corner] * m[q];                  // eq. 2.4.1, lumped
                p[i] += N[q][corner] * m[q] * v[q];
                f[i] -= V[q] * (sigma[q] * dN[q][corner]);       // eq. 2.3.8
            }
        }
        std::vector<Eigen::Vector3d> vn(nn, Eigen::Vector3d::Zero()), an(nn, Eigen::Vector3d::Zero());
        const double lightNode = 1e-9 * *std::min_element(m.begin(), m.end());
        for (int i = 0; i < nn; ++i) {
            if (mass[i] <= 0) continue;
            if (mass[i] > lightNode) an[i] = f[i] / mass[i];    // eq. 2.4.2
            vn[i] = p[i] / mass[i] + dt * an[i];                 // eq. 2.4.3
        }
        const double K = E / (3 * (1 - 2 * nu)), G = E / (2 * (1 + nu));
        for (std::size_t q = 0; q < np; ++q) {
            Eigen::Matrix3d L = Eigen::Matrix3d::Zero();
            Eigen::Vector3d u = Eigen::Vector3d::Zero(), a = Eigen::Vector3d::Zero();
            for (int corner = 0; corner < 8; ++corner) {
                const int i = nodes[q][corner];
                L += vn[i] * dN[q][corner].transpose();
                u += N[q][corner] * vn[i];
                a += N[q][corner] * an[i];
            }
            // Turn the stress by the step's spin (Rodrigues), then add the elastic increment.
            const Eigen::Matrix3d W = 0.5 * dt * (L - L.transpose());
            const double t = std::sqrt(W(0, 1) * W(0, 1) + W(1, 2) * W(1, 2) + W(0, 2) * W(0, 2));
            Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
            if (t > 0) R += std::sin(t) / t * W + (1 - std::cos(t)) / (t * t) * W * W;
            sigma[q] = R * sigma[q] * R.transpose();
            const Eigen::Matrix3d eps = 0.5 * dt * (L + L.transpose());
            sigma[q] += (K - 2 * G / 3) * eps.trace() * Eigen::Matrix3d::Identity() + 2 * G * eps;  // eq. H.2.1
            V[q] *= (Eigen::Matrix3d::Identity() + dt * L).determinant();
            x[q] += dt * u;                                      // eq. 2.4.7
            v[q] += dt * a;                                      // eq. 2.4.8 (FLIP)
        }
    }
};

} // namespace

TEST(ReferenceMpm3D, engineMatchesTheReferenceThroughASphereImpact)
{
    // Two rubber spheres (r 0.2 m, E 1 kPa, rho 1000) meet at 0.57 m/s in a box of free sides;
    // 1 s at dt 1e-3 runs 0.2 s into the impact, where every term acts.
    ScratchDir scratch("reference3d");
    const fs::path dir = scratch.path();
    writeDictionary(dir / "constant/grid", "origin (0 0 0); cellSize 0.05; nCells (20 20 10);\n"
                                           "boundaries { left { type free; } right { type free; } bottom { type free; } "
                                           "top { type free; } back { type free; } front { type free; } }\n");
    writeDictionary(dir / "constant/materials", "rubber { type linearElastic; rho 1000; E 1000; nu 0.3; }\n");
    writeDictionary(dir / "constant/bodies",
                    "lowerLeft { material rubber; shape { type sphere; centre (0.2 0.2 0.25); radius 0.2; } "
                    "particlesPerCell 2; velocity (0.2 0.2 0); }\n"
                    "upperRight { material rubber; shape { type sphere; centre (0.8 0.8 0.25); radius 0.2; } "
                    "particlesPerCell 2; velocity (-0.2 -0.2 0); }\n");
    writeDictionary(dir / "system/controlDict", "startFrom latestTime;\nstartTime 0;\nstopAt endTime;\nendTime 1;\n"
                                                "deltaT 1e-3;\nwriteControl adjustableRunTime;\nwriteInterval 10;\n");
    writeDictionary(dir / "system/mpmSchemes", "updateScheme USL;\nshapeFunction bilinear;\ntransfer FLIP;\n"
                                               "sortInterval 100;\n");
    const auto simulation = initialisedSimulation<3>(dir);

    const gpic::Particles<3>& p0 = simulation->solver().particles();
    ReferenceMpm3D ref{{20, 20, 10}, 0.05, 1000, 0.3, {}, {}, {}, {}, {}};
    std::map<int, std::size_t> refIndex;  // the engine sorts its particles by cell: match by id
    for (std::size_t q = 0; q < p0.size(); ++q) {
        refIndex[p0.id[q]] = q;
        ref.x.push_back(p0.x[q]);
        ref.v.push_back(p0.v[q]);
        ref.m.push_back(p0.m[q]);
        ref.V.push_back(p0.V[q]);
        ref.sigma.push_back(Eigen::Matrix3d::Zero());
    }
    simulation->run();
    for (int k = 0; k < 1000; ++k) ref.step(1e-3);

    // Same algorithm, different summation order: agreement to round-off growth.
    const gpic::Particles<3>& p = simulation->solver().particles();
    double dx = 0, dv = 0, ds = 0, smax = 0;
    using gpic::XX, gpic::YY, gpic::ZZ, gpic::XY, gpic::YZ, gpic::XZ;
    for (std::size_t q = 0; q < p.size(); ++q) {
        const std::size_t r = refIndex.at(p.id[q]);
        dx = std::max(dx, (p.x[q] - ref.x[r]).norm());
        dv = std::max(dv, (p.v[q] - ref.v[r]).norm());
        const Eigen::Matrix3d& s = ref.sigma[r];
        const double engine[6] = {p.sigma[q][XX], p.sigma[q][YY], p.sigma[q][ZZ],
                                  p.sigma[q][XY], p.sigma[q][YZ], p.sigma[q][XZ]};
        const double reference[6] = {s(0, 0), s(1, 1), s(2, 2), s(0, 1), s(1, 2), s(0, 2)};
        for (int c = 0; c < 6; ++c) ds = std::max(ds, std::abs(engine[c] - reference[c]));
        smax = std::max(smax, s.cwiseAbs().maxCoeff());
    }
    EXPECT_GT(smax, 10.0) << "the spheres must be in contact and stressed";
    EXPECT_LT(dx, 1e-9);
    EXPECT_LT(dv, 1e-9);
    EXPECT_LT(ds, 1e-9 * smax);
}
