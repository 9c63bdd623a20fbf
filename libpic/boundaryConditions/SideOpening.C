#include "boundaryConditions/SideOpening.H"

#include "dictionary/Dictionary.H"

#include <vector>

namespace gpic {

template <int D> SideOpening<D>::SideOpening(const Dictionary& dict)
{
    if (!dict.found("opening")) return;
    if constexpr (D == 2) {
        const auto ab = dict.getChecked<std::vector<double>>(
            "opening", [](const std::vector<double>& v) { return v.size() == 2 && v[0] < v[1]; },
            "two coordinates along the side (a b) with a < b");
        kind_ = Kind::box;
        low_[0] = ab[0];
        high_[0] = ab[1];
    } else {
        if (!dict.isDict("opening"))
            dict.fail("opening", "a side of a 3D grid opens on a rectangle, opening { min (a1 a2); max (b1 b2); }, "
                                 "or a disc, opening { centre (c1 c2); radius r; }");
        const Dictionary& o = dict.subDict("opening");
        if (o.found("radius")) {
            kind_ = Kind::circle;
            centre_ = o.get<Eigen::Vector2d>("centre");
            radius_ = o.getChecked<double>("radius", [](const double& r) { return r > 0; }, "radius > 0");
        } else {
            kind_ = Kind::box;
            low_ = o.get<Eigen::Vector2d>("min");
            high_ = o.getChecked<Eigen::Vector2d>(
                "max", [this](const Eigen::Vector2d& b) { return (b.array() > low_.array()).all(); },
                "both coordinates above those of min");
        }
    }
}

template class SideOpening<2>;
#if GPIC_WITH_3D
template class SideOpening<3>;
#endif

} // namespace gpic
