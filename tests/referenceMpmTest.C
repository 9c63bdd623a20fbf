// A small, independent MPM (USL, bilinear cells, lumped mass, FLIP update, linear
// elasticity with the rotated stress) written straight from the seed's eqs. 2.4.1-2.4.8 and
// H.2.1, against which the engine is compared on the two-disk case. It guards the engine's
// structure (weights cache, blocks, update-scheme verbs) against changes that alter results.
// The particle velocity may blend FLIP with PIC (mpmSchemes `flipFraction`):
//     v_p <- f (v_p + dt sum_i N_ip a_i) + (1 - f) sum_i N_ip v_i^{t+1}.
#include "support/CaseRunner.H"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

using namespace gpic::test;

namespace {

struct ReferenceMpm {
    // Grid: nx x ny cells of size h from the origin (0, 0); no boundary constraint (free sides).
    int nx, ny;
    double h;
    // Material.
    double E, nu;
    // Particles.
    std::vector<double> x, y, vx, vy, m, V, s11, s22, s33, s12;
    double flip = 1.0;  // FLIP share of the velocity update

    void step(double dt)
    {
        const int nn = (nx + 1) * (ny + 1);
        std::vector<double> mass(nn, 0), px(nn, 0), py(nn, 0), fx(nn, 0), fy(nn, 0);
        const std::size_t np = x.size();
        std::vector<std::array<int, 4>> node(np);
        std::vector<std::array<double, 4>> N(np), Nx(np), Ny(np);
        for (std::size_t p = 0; p < np; ++p) {
            const int i = std::min(nx - 1, int(std::floor(x[p] / h)));
            const int j = std::min(ny - 1, int(std::floor(y[p] / h)));
            const double xi = x[p] / h - i, eta = y[p] / h - j;
            node[p] = {i + j * (nx + 1), i + 1 + j * (nx + 1), i + 1 + (j + 1) * (nx + 1), i + (j + 1) * (nx + 1)};
            N[p] = {(1 - xi) * (1 - eta), xi * (1 - eta), xi * eta, (1 - xi) * eta};
            Nx[p] = {-(1 - eta) / h, (1 - eta) / h, eta / h, -eta / h};
            Ny[p] = {-(1 - xi) / h, -xi / h, xi / h, (1 - xi) / h};
            for (int a = 0; a < 4; ++a) {
                const int n = node[p][a];
                mass[n] += N[p][a] * m[p];                    // eq. 2.4.1, lumped
                px[n] += N[p][a] * m[p] * vx[p];
                py[n] += N[p][a] * m[p] * vy[p];
                fx[n] -= V[p] * (s11[p] * Nx[p][a] + s12[p] * Ny[p][a]);  // eq. 2.3.8
                fy[n] -= V[p] * (s12[p] * Nx[p][a] + s22[p] * Ny[p][a]);
            }
        }
        std::vector<double> vnx(nn, 0), vny(nn, 0), ax(nn, 0), ay(nn, 0);
        const double lightNode = 1e-9 * *std::min_element(m.begin(), m.end());
        for (int n = 0; n < nn; ++n) {
            if (mass[n] <= 0) continue;
            // Nodes lighter than 1e-9 of a particle get no acceleration (the engine's guard
            // against the small-mass instability of USL).
            ax[n] = mass[n] > lightNode ? fx[n] / mass[n] : 0.0;  // eq. 2.4.2
            ay[n] = mass[n] > lightNode ? fy[n] / mass[n] : 0.0;
            vnx[n] = px[n] / mass[n] + dt * ax[n];             // eq. 2.4.3
            vny[n] = py[n] / mass[n] + dt * ay[n];
        }
        const double K = E / (3 * (1 - 2 * nu)), G = E / (2 * (1 + nu));
        const double a1 = K + 4 * G / 3, a2 = K - 2 * G / 3;
        for (std::size_t p = 0; p < np; ++p) {
            double L11 = 0, L12 = 0, L21 = 0, L22 = 0, ux = 0, uy = 0, gx = 0, gy = 0;
            for (int a = 0; a < 4; ++a) {
                const int n = node[p][a];
                L11 += vnx[n] * Nx[p][a]; L12 += vnx[n] * Ny[p][a];
                L21 += vny[n] * Nx[p][a]; L22 += vny[n] * Ny[p][a];
                ux += N[p][a] * vnx[n]; uy += N[p][a] * vny[n];
                gx += N[p][a] * ax[n]; gy += N[p][a] * ay[n];
            }
            // Rotate the stress by the spin of the step, then add the elastic increment.
            const double w = 0.5 * dt * (L12 - L21), c = std::cos(w), s = std::sin(w);
            const double a = s11[p], b = s12[p], d = s22[p];
            s11[p] = c * c * a + 2 * s * c * b + s * s * d;
            s22[p] = s * s * a - 2 * s * c * b + c * c * d;
            s12[p] = s * c * (d - a) + (c * c - s * s) * b;
            const double e11 = dt * L11, e22 = dt * L22, e12 = 0.5 * dt * (L12 + L21);
            s11[p] += a1 * e11 + a2 * e22;                     // eq. H.2.1
            s22[p] += a2 * e11 + a1 * e22;
            s33[p] += a2 * (e11 + e22);
            s12[p] += 2 * G * e12;
            V[p] *= (1 + dt * L11) * (1 + dt * L22) - dt * dt * L12 * L21;
            x[p] += dt * ux;                                   // eq. 2.4.7
            y[p] += dt * uy;
            vx[p] = flip * (vx[p] + dt * gx) + (1 - flip) * ux;  // eq. 2.4.8, blended
            vy[p] = flip * (vy[p] + dt * gy) + (1 - flip) * uy;
        }
    }
};

} // namespace

namespace {

//- 1.7 s at dt 1e-3: through first contact (1.3 s) into the impact, where every term acts.
void compareThroughTheDiskImpact(double flipFraction)
{
    ScratchDir scratch("reference");
    const fs::path dir = scratch.path() / "twoDisks";
    copyCase(tutorialPath("verification/twoDisks"), dir);
    setEntry(dir / "system/controlDict", "endTime", "1.7");
    setEntry(dir / "system/controlDict", "writeInterval", "10");
    setEntry(dir / "system/mpmSchemes", "updateScheme", "USL");
    setEntry(dir / "system/mpmSchemes", "shapeFunction", "bilinear");
    if (flipFraction < 1) setEntry(dir / "system/mpmSchemes", "flipFraction", std::to_string(flipFraction));
    const auto simulationPtr = initialisedSimulation(dir);
    gpic::Simulation<2>& simulation = *simulationPtr;

    // The reference starts from the same particles.
    const gpic::Particles<2>& p0 = simulation.solver().particles();
    ReferenceMpm ref{25, 25, 0.04, 1000, 0.3, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, flipFraction};
    std::map<int, std::size_t> refIndex;  // the engine sorts its particles by cell: match by id
    for (std::size_t q = 0; q < p0.size(); ++q) {
        refIndex[p0.id[q]] = q;
        ref.x.push_back(p0.x[q].x()); ref.y.push_back(p0.x[q].y());
        ref.vx.push_back(p0.v[q].x()); ref.vy.push_back(p0.v[q].y());
        ref.m.push_back(p0.m[q]); ref.V.push_back(p0.V[q]);
        ref.s11.push_back(0); ref.s22.push_back(0); ref.s33.push_back(0); ref.s12.push_back(0);
    }
    simulation.run();
    for (int k = 0; k < 1700; ++k) ref.step(1e-3);

    // Same algorithm, different summation order: agreement to round-off growth.
    const gpic::Particles<2>& p = simulation.solver().particles();
    double dx = 0, dv = 0, ds = 0, smax = 0;
    for (std::size_t q = 0; q < p.size(); ++q) {
        const std::size_t r = refIndex.at(p.id[q]);
        dx = std::max(dx, std::hypot(p.x[q].x() - ref.x[r], p.x[q].y() - ref.y[r]));
        dv = std::max(dv, std::hypot(p.v[q].x() - ref.vx[r], p.v[q].y() - ref.vy[r]));
        ds = std::max({ds, std::abs(p.sigma[q][gpic::XX] - ref.s11[r]), std::abs(p.sigma[q][gpic::YY] - ref.s22[r]),
                       std::abs(p.sigma[q][gpic::ZZ] - ref.s33[r]), std::abs(p.sigma[q][gpic::XY] - ref.s12[r])});
        smax = std::max(smax, std::abs(ref.s22[r]));
    }
    EXPECT_GT(smax, 10.0) << "the disks must be in contact and stressed";
    EXPECT_LT(dx, 1e-9);
    EXPECT_LT(dv, 1e-9);
    EXPECT_LT(ds, 1e-9 * smax);
}

} // namespace

TEST(ReferenceMpm, engineMatchesTheReferenceThroughTheDiskImpact) { compareThroughTheDiskImpact(1.0); }

// The same with 10 % PIC in the particle velocity update.
TEST(ReferenceMpm, engineMatchesTheReferenceWithAFlipPicBlend) { compareThroughTheDiskImpact(0.9); }
