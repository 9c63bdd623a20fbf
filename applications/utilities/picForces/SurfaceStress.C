#include "SurfaceStress.H"

#include "core/error.H"
#include "grid/FaceBand.H"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace gpic {

std::vector<SurfaceStation> surfaceStress(const GridContactForces& grid, const Vector2& p0, const Vector2& p1,
                                          double band)
{
    if (!((p1 - p0).norm() > 0.0)) throw InputError("", 0, "-surface: the two ends of the face coincide");
    const double h = grid.spacing.maxCoeff();
    const FaceBand face(p0, p1, h, band);
    const double L = face.length();
    const Vector2 t = face.tangent(), n = face.normal();
    band = face.band();

    // Nodes along the face, as (s, force).
    std::vector<std::pair<double, Vector2>> nodes;
    for (std::size_t k = 0; k < grid.force.size(); ++k) {
        if (grid.force[k].isZero(0.0)) continue;
        if (const auto s = face.station(grid.position[k])) nodes.emplace_back(*s, grid.force[k]);
    }
    if (nodes.empty()) {
        std::ostringstream msg;
        msg << "-surface: no node with a contact force along (" << p0.x() << ' ' << p0.y() << ") -> (" << p1.x()
            << ' ' << p1.y() << ") within " << band
            << " m on the material side (the material must lie to the right of the face: list the ends "
               "counter-clockwise around the body)";
        throw InputError("", 0, msg.str());
    }
    std::sort(nodes.begin(), nodes.end(), [](const auto& a, const auto& b) { return a.first < b.first; });

    std::vector<SurfaceStation> stations;
    for (const auto& [s, f] : nodes) {
        if (stations.empty() || s - stations.back().s > 1e-3 * h) {
            stations.emplace_back();
            stations.back().s = s;
            stations.back().x = face.point(s);
        }
        stations.back().Fn += f.dot(n);
        stations.back().Ft += f.dot(t);
    }
    for (std::size_t k = 0; k < stations.size(); ++k) {
        const double from = k == 0 ? 0.0 : 0.5 * (stations[k - 1].s + stations[k].s);
        const double to = k + 1 == stations.size() ? L : 0.5 * (stations[k].s + stations[k + 1].s);
        SurfaceStation& st = stations[k];
        st.length = to - from;
        st.normal = st.length > 0 ? -st.Fn / st.length : 0.0;
        st.shear = st.length > 0 ? st.Ft / st.length : 0.0;
    }
    return stations;
}

} // namespace gpic
