#include "PassivePressure.H"

#include "core/error.H"

#include <algorithm>
#include <limits>
#include <sstream>
#include <string>

namespace gpic {

namespace {

//- One node of the characteristic net.
struct Node {
    double x = 0.0;    //- [m]
    double y = 0.0;    //- depth [m]
    double s = 0.0;    //- reduced mean stress [Pa]
    double psi = 0.0;  //- angle of sigma_1 from +x [rad]
};

std::string degrees(double radians)
{
    std::ostringstream out;
    out.precision(6);
    out << radians * 180 / M_PI << " deg";
    return out.str();
}

void require(bool ok, const std::string& message)
{
    if (!ok) throw InputError("", 0, message);
}

//- The constants of the characteristic relations.
struct Soil {
    double tanPhi, mu, gamma;
};

//- The node where the alpha line through a meets the beta line through b: both lines and
//  both relations by the trapezoidal rule (slopes and s tan(phi) averaged over the segment),
//  iterated from the mean of a and b.
Node interiorNode(const Node& a, const Node& b, const Soil& soil)
{
    Node p{0.5 * (a.x + b.x), 0.5 * (a.y + b.y), 0.5 * (a.s + b.s), 0.5 * (a.psi + b.psi)};
    const double dx = b.x - a.x, dy = b.y - a.y;
    for (int iteration = 0; iteration < 100; ++iteration) {
        const double ea = 0.5 * (a.psi + p.psi) - soil.mu;  // alpha direction
        const double eb = 0.5 * (b.psi + p.psi) + soil.mu;  // beta direction
        // a + la (cos ea, sin ea) = b + lb (cos eb, sin eb); the two differ by about 2 mu.
        const double la = (dy * std::cos(eb) - dx * std::sin(eb)) / std::sin(ea - eb);
        Node next;
        next.x = a.x + la * std::cos(ea);
        next.y = a.y + la * std::sin(ea);
        const double A = (a.s + p.s) * soil.tanPhi;  // 2 sbar tan(phi) on the alpha segment
        const double B = (b.s + p.s) * soil.tanPhi;  // and on the beta segment
        const double Ra = a.s - A * a.psi + soil.gamma * ((next.y - a.y) - soil.tanPhi * (next.x - a.x));
        const double Rb = b.s + B * b.psi + soil.gamma * ((next.y - b.y) + soil.tanPhi * (next.x - b.x));
        next.psi = (Rb - Ra) / (A + B);
        next.s = Ra + A * next.psi;
        const double scale = std::max({a.s, b.s, std::abs(next.s)});
        const bool done = std::abs(next.psi - p.psi) < 1e-14 && std::abs(next.s - p.s) <= 1e-14 * scale;
        p = next;
        if (done) return p;
        if (!std::isfinite(p.s) || !std::isfinite(p.psi)) break;
    }
    std::ostringstream out;
    out << "the characteristic net did not converge near (x, depth) = (" << p.x << ", " << p.y << ") m";
    throw RunError(out.str());
}

//- The node where the alpha line through a meets the wall, on which psi = psiW.
Node wallNode(const Node& a, double psiW, double wallAngle, const Soil& soil)
{
    const double ea = 0.5 * (a.psi + psiW) - soil.mu;
    // a + la (cos ea, sin ea) = lw (cos wallAngle, sin wallAngle)
    const double lw = (a.x * std::sin(ea) - a.y * std::cos(ea)) / std::sin(ea - wallAngle);
    Node w{lw * std::cos(wallAngle), lw * std::sin(wallAngle), 0.0, psiW};
    const double turn = soil.tanPhi * (psiW - a.psi);
    w.s = (a.s * (1 + turn) + soil.gamma * ((w.y - a.y) - soil.tanPhi * (w.x - a.x))) / (1 - turn);
    if (!(1 - turn > 0) || !std::isfinite(w.s)) throw RunError("the characteristic net folded at the wall");
    return w;
}

double distanceAlongWall(const Node& w, double wallAngle)
{
    return w.x * std::cos(wallAngle) + w.y * std::sin(wallAngle);
}

} // namespace

double rankinePassive(double phi)
{
    const double t = std::tan(M_PI / 4 + phi / 2);
    return t * t;
}

PassivePressure::PassivePressure(const PassiveProblem& problem, int resolution) : p_(problem), n_(resolution)
{
    const double eps = 1e-12;
    require(std::isfinite(p_.phi) && p_.phi > 0 && p_.phi < M_PI / 2,
            "phi = " + degrees(p_.phi) + ": the friction angle must lie in 0 < phi < 90 deg");
    require(std::isfinite(p_.delta) && p_.delta >= 0 && p_.delta <= p_.phi * (1 + eps),
            "delta = " + degrees(p_.delta) + ": the wall friction angle must lie in 0 <= delta <= phi (" +
                degrees(p_.phi) + ")");
    require(std::isfinite(p_.gamma) && p_.gamma >= 0, "gamma must be >= 0 (unit weight rho g, N/m^3)");
    require(std::isfinite(p_.c) && p_.c >= 0, "c must be >= 0 (cohesion, Pa)");
    require(std::isfinite(p_.q) && p_.q >= 0, "q must be >= 0 (surcharge on the free surface, Pa)");
    require(p_.gamma > 0 || p_.c > 0 || p_.q > 0, "nothing loads the soil: give gamma > 0, c > 0 or q > 0");
    require(std::isfinite(p_.wallAngle) && p_.wallAngle > 0 && p_.wallAngle < M_PI,
            "wallAngle = " + degrees(p_.wallAngle) + ": must lie in 0 < wallAngle < 180 deg");
    require(resolution >= 2, "the resolution n must be >= 2");

    // At delta = phi the wall itself is a beta line; a wall friction a hair below phi gives
    // the same pressures (the limit is continuous) and keeps the wall zone open.
    p_.delta = std::min(p_.delta, p_.phi * (1 - 1e-9));
    const double Delta = std::asin(std::sin(p_.delta) / std::sin(p_.phi));
    psiN_ = p_.wallAngle - M_PI / 2;
    psiW_ = psiN_ + 0.5 * (Delta + p_.delta);
    require(psiW_ >= -eps, "wallAngle = " + degrees(p_.wallAngle) + " with delta = " + degrees(p_.delta) +
                               " would need a stress discontinuity at the wall top (fan angle " +
                               degrees(psiW_) + " < 0), which this solver does not model; use wallAngle >= " +
                               degrees(M_PI / 2 - 0.5 * (Delta + p_.delta)));
    psiW_ = std::max(psiW_, 0.0);
}

PassiveSolution PassivePressure::solve(double h) const
{
    if (!(std::isfinite(h) && h > 0)) throw InputError("", 0, "the wall depth h must be > 0");
    const double phi = p_.phi, k = std::sin(phi), H = p_.c / std::tan(phi), omega = p_.wallAngle;
    const Soil soil{std::tan(phi), M_PI / 4 - phi / 2, p_.gamma};
    const double length = h / std::sin(omega);  // along the wall

    PassiveSolution out;
    out.h = h;
    const int fanRays = psiW_ > 0 ? std::max(1, int(std::ceil(n_ * psiW_ / (M_PI / 4)))) : 0;
    out.fanRays = fanRays;

    // Row 0: the fan at O, where the alpha relation over zero length is ds = 2 s tan(phi) dpsi.
    const double sRankine = (p_.q + H) / (1 - k);
    std::vector<Node> previous(fanRays + 1), current;
    for (int i = 0; i <= fanRays; ++i) {
        const double psi = fanRays ? psiW_ * i / fanRays : psiW_;
        previous[i] = Node{0.0, 0.0, sRankine * std::exp(2 * psi * soil.tanPhi), psi};
    }
    std::vector<Node> wall{previous.back()};

    // One alpha line from radius r on OA to the wall: current = row j from previous = row j-1.
    auto alphaLine = [&](double r, int j) {
        current.resize(fanRays + j + 1);
        const double x = r * std::cos(soil.mu), y = r * std::sin(soil.mu);
        current[0] = Node{x, y, (p_.q + H + p_.gamma * y) / (1 - k), 0.0};  // Rankine zone
        for (int i = 1; i < fanRays + j; ++i) current[i] = interiorNode(current[i - 1], previous[i], soil);
        current[fanRays + j] = wallNode(current[fanRays + j - 1], psiW_, omega, soil);
        out.nodes += fanRays + j;
        return distanceAlongWall(current.back(), omega);
    };

    const double growth = std::exp(2.0 / n_);
    double rLast = 0.0, lLast = 0.0;
    double r = 1e-6 * length;
    for (int j = 1;; ++j) {
        if (j > 200 * n_ + 1000) throw RunError("the characteristic net did not reach the wall foot");
        double l = alphaLine(r, j);
        if (!(l > lLast)) throw RunError("the characteristic net folded: the alpha lines do not move down the wall");
        if (l >= length) {
            // The last alpha line ends at the foot: regula falsi (Illinois) on its start radius,
            // bracketed by the previous line (above the foot) and this one (at or below it).
            double r0 = rLast, f0 = lLast - length, r1 = r, f1 = l - length, f = f1;
            for (int iteration = 0, side = 0; std::abs(f) > 1e-13 * length; ++iteration) {
                if (iteration == 200) throw RunError("the last alpha line does not find the wall foot");
                r = (r0 * f1 - r1 * f0) / (f1 - f0);
                f = alphaLine(r, j) - length;
                if (f < 0) {
                    r0 = r, f0 = f;
                    if (side == -1) f1 *= 0.5;
                    side = -1;
                } else {
                    r1 = r, f1 = f;
                    if (side == +1) f0 *= 0.5;
                    side = +1;
                }
            }
            wall.push_back(current.back());
            out.alphaLines = j;
            break;
        }
        wall.push_back(current.back());
        previous.swap(current);
        rLast = r, lLast = l;
        r *= growth;
    }

    // Stresses on the wall and their resultant (trapezoidal rule between the wall nodes).
    const double obliquity = wallObliquity();
    for (const Node& w : wall) {
        WallStress ws;
        ws.depth = w.y;
        ws.distance = distanceAlongWall(w, omega);
        ws.normal = w.s * (1 + k * std::cos(obliquity)) - H;
        ws.shear = w.s * k * std::sin(obliquity);
        out.wall.push_back(ws);
    }
    for (std::size_t m = 1; m < out.wall.size(); ++m) {
        const WallStress &a = out.wall[m - 1], &b = out.wall[m];
        out.normalForce += 0.5 * (a.normal + b.normal) * (b.distance - a.distance);
        out.shearForce += 0.5 * (a.shear + b.shear) * (b.distance - a.distance);
    }
    const double N = out.normalForce, T = out.shearForce;
    out.Pp = std::hypot(N, T);
    // The wall pushes the soil with N along the normal n = (sin w, -cos w) (x, depth) and drags
    // it with T down the wall t = (cos w, sin w); x2 points up, against the depth.
    out.Fx1 = N * std::sin(omega) + T * std::cos(omega);
    out.Fx2 = -(-N * std::cos(omega) + T * std::sin(omega));
    const double weight = 0.5 * p_.gamma * h * h;
    out.Kp = weight > 0 ? out.Pp / weight : std::numeric_limits<double>::quiet_NaN();
    out.Kpn = weight > 0 ? N / weight : std::numeric_limits<double>::quiet_NaN();

    // Rupture line: the straight alpha line of the Rankine zone from the free surface to OA,
    // then the last alpha line to the foot.
    auto rupturePoint = [&](double x, double y, double s, double psi) {
        return RupturePoint{x, y, s * (1 + k * std::cos(2 * psi)) - H, s * (1 - k * std::cos(2 * psi)) - H,
                            s * k * std::sin(2 * psi)};
    };
    const Node& A = current.front();
    out.ruptureLine.push_back(rupturePoint(A.x + A.y / std::tan(soil.mu), 0.0, sRankine, 0.0));
    for (const Node& node : current) out.ruptureLine.push_back(rupturePoint(node.x, node.y, node.s, node.psi));
    return out;
}

ConvergedPassive solveConverged(const PassiveProblem& problem, double h, int n0, double tolerance, int nMax)
{
    if (!(tolerance > 0)) throw InputError("", 0, "the tolerance must be > 0");
    ConvergedPassive result;
    int n = std::max(2, n0);
    PassiveSolution coarse = PassivePressure(problem, n).solve(h);
    for (;;) {
        if (2 * n > nMax) {
            if (result.resolution == 0) throw InputError("", 0, "the resolution n must be at most " + std::to_string(nMax / 2));
            std::ostringstream out;
            out << "the passive force did not converge to " << tolerance << " by resolution n = " << n
                << " (last change " << result.change << ")";
            throw RunError(out.str());
        }
        n *= 2;
        PassiveSolution fine = PassivePressure(problem, n).solve(h);
        result.change = std::abs(fine.Pp - coarse.Pp) / std::max(fine.Pp, 1e-300);
        result.solution = std::move(fine);
        result.resolution = n;
        if (result.change < tolerance) return result;
        coarse = result.solution;
    }
}

} // namespace gpic
