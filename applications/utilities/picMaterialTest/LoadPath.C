#include "LoadPath.H"

#include "dictionary/Dictionary.H"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace gpic {

namespace {

//- A tensor strain component of this small-strain driver.
double readStrain(const Dictionary& dict, const std::string& key)
{
    return dict.getChecked<double>(
        key, [](const double& v) { return std::isfinite(v) && std::abs(v) < 1.0; },
        "-1 < " + key + " < 1 (a small tensor strain)");
}

double readFinite(const Dictionary& dict, const std::string& key, const std::string& what)
{
    return dict.getChecked<double>(key, [](const double& v) { return std::isfinite(v); },
                                   "a finite " + what);
}

//- An anticlockwise rotation by `degrees` as the spin w12 = (dv1/dx2 - dv2/dx1)/2 it
//  takes: for v = Omega x (-x2, x1), w12 = -Omega.
double spinOfRotation(double degrees) { return -degrees * M_PI / 180.0; }

std::string number(double v)
{
    std::ostringstream s;
    s.precision(17);
    s << v;
    return s.str();
}

} // namespace

template <int D> int csvColumn(const std::string& name)
{
    static const std::vector<std::string> plane{"step", "eps11", "eps22", "eps12", "sigma11", "sigma22", "sigma33",
                                                "sigma12", "p", "q"};
    static const std::vector<std::string> solid{"step", "eps11", "eps22", "eps33", "eps12", "eps23", "eps13",
                                                "sigma11", "sigma22", "sigma33", "sigma12", "sigma23", "sigma13",
                                                "p", "q"};
    const auto& names = D == 2 ? plane : solid;
    return static_cast<int>(std::find(names.begin(), names.end(), name) - names.begin()) + 1;
}

template <int D> const std::vector<std::string>& LoadPath<D>::pathNames()
{
    static const std::vector<std::string> names{"oedometer", "biaxial", "simpleShear", "rotation",
                                                "general"};
    return names;
}

template <int D>
LoadPath<D>::LoadPath(const Dictionary& dict)
    : type_(dict.getWord("path", pathNames())),
      steps_(dict.getChecked<int>("steps", [](const int& n) { return n >= 1 && n <= 100000000; },
                                  "1 <= steps <= 100000000"))
{
    if (type_ == "oedometer" || type_ == "biaxial") {
        strain_[YY] = readStrain(dict, "strain");
        axialSign_ = strain_[YY] < 0 ? -1 : 1;
    }
    if (type_ == "biaxial") {
        // The lateral stress is a compression held from the first step: sigma11 = -confining.
        const double confining = dict.getChecked<double>(
            "confining", [](const double& v) { return std::isfinite(v) && v >= 0; },
            "confining >= 0 (the lateral compressive stress, Pa)");
        stressControlled_[0] = true;
        sigmaEnd_[XX] = -confining;
        if constexpr (D == 3) sigmaEnd_[ZZ] = -confining;  // the triaxial test: eps33 follows eps11
        held_ = true;
    } else if (type_ == "simpleShear") {
        const double gamma = dict.getChecked<double>(
            "gamma", [](const double& v) { return std::isfinite(v) && std::abs(v) < 2.0; },
            "-2 < gamma < 2 (eps12 = gamma/2 is a small strain)");
        strain_[XY] = 0.5 * gamma;
        // v1 = gamma_dot x2 turns the material as it shears: w12 = d gamma / 2. Without
        // spin the same strain is a pure shear along the diagonals.
        if (dict.getOrDefault<bool>("spin", true)) omega_ = 0.5 * gamma;
    } else if (type_ == "rotation") {
        omega_ = spinOfRotation(readFinite(dict, "angle", "angle in degrees (anticlockwise)"));
    } else if (type_ == "general") {
        readGeneral(dict);
    }
}

template <int D> void LoadPath<D>::readGeneral(const Dictionary& dict)
{
    for (int c = 0; c < Controlled<D>::n; ++c) {
        const std::string epsKey = std::string("eps") + Controlled<D>::name(c);
        const std::string sigmaKey = std::string("sigma") + Controlled<D>::name(c);
        const int k = Controlled<D>::component()[c];
        if (dict.found(sigmaKey)) {
            if (dict.found(epsKey))
                dict.fail(sigmaKey, "give either " + epsKey + " or " + sigmaKey + " in test " +
                                        dict.name() + ", not both");
            stressControlled_[c] = true;
            sigmaEnd_[k] = readFinite(dict, sigmaKey, "stress in Pa (tension positive)");
        } else if (dict.found(epsKey)) {
            strain_[k] = readStrain(dict, epsKey);
        }
    }
    // A ring of an axisymmetric scene stretches around the axis: eps33 is then the hoop strain,
    // imposed (doc/axisymmetric.md); without it the point is in plane strain.
    if (D == 2 && dict.found("eps33")) strain_[ZZ] = readStrain(dict, "eps33");
    if (dict.found("angle"))
        omega_ = spinOfRotation(readFinite(dict, "angle", "angle in degrees (anticlockwise)"));
    // There and back: a point loaded and unloaded along the same path in one test keeps its
    // state between the two (a material that separates and re-forms, a hysteresis loop).
    back_ = dict.getOrDefault<bool>("back", false);
    if (back_ && steps_ % 2 != 0)
        dict.fail("steps", "keyword 'steps' in test " + dict.name() + ": value " + std::to_string(steps_) +
                               " is not valid; requires an even number with 'back yes' (half out, half back)");
}

template <int D> typename Space<D>::SymTensor LoadPath<D>::defaultStartStress() const
{
    SymTensor s = SymTensor::Zero();
    if (type_ == "biaxial")
        for (int a = 0; a < 3; ++a) s[a] = sigmaEnd_[XX];
    return s;
}

template <int D> bool LoadPath<D>::hasStressControl() const
{
    for (bool c : stressControlled_)
        if (c) return true;
    return false;
}

template <int D> StepControl<D> LoadPath<D>::step(int n, const SymTensor& startStress) const
{
    StepControl<D> control;
    // Out over all steps, or with `back` out over the first half and back over the second.
    const int out = back_ ? steps_ / 2 : steps_;
    const bool returning = n > out;
    control.dEps = strain_ / out;
    if (returning) control.dEps = -control.dEps;
    const double dOmega12 = returning ? -(omega_ / out) : omega_ / out;
    if constexpr (D == 2) control.dOmega = dOmega12;
    else control.dOmega = typename Space<D>::Spin(dOmega12, 0.0, 0.0);  // w12: about e3
    control.stressControlled = stressControlled_;
    control.eps33FollowsEps11 = D == 3 && type_ == "biaxial";
    const double fraction = static_cast<double>(returning ? steps_ - n : n) / out;
    for (int c = 0; c < Controlled<D>::n; ++c) {
        if (!stressControlled_[c]) continue;
        const int k = Controlled<D>::component()[c];
        control.dEps[k] = 0;
        control.sigmaTarget[k] =
            held_ ? sigmaEnd_[k] : startStress[k] + fraction * (sigmaEnd_[k] - startStress[k]);
    }
    return control;
}

template <int D> NaturalAxes LoadPath<D>::naturalAxes() const
{
    NaturalAxes axes;
    const auto col = [](const char* name) { return "$" + std::to_string(csvColumn<D>(name)); };
    axes.pColumn = csvColumn<D>("p");
    axes.qColumn = csvColumn<D>("q");
    const std::string s = axialSign_ < 0 ? "-" : "";
    const std::string compression = axialSign_ < 0 ? ", compression positive" : "";
    if (type_ == "oedometer") {
        axes.xExpression = s + col("eps22");
        axes.xLabel = s + "eps22 [-]";
        axes.curves = {{s + col("sigma22"), s + "sigma22"}, {s + col("sigma11"), s + "sigma11"}, {s + col("sigma33"), s + "sigma33"}};
        axes.yLabel = "stress [Pa]" + compression;
    } else if (type_ == "biaxial") {
        axes.xExpression = s + col("eps22");
        axes.xLabel = s + "eps22 (axial strain) [-]";
        axes.curves = {{s + "(" + col("sigma22") + "-" + col("sigma11") + ")", s + "(sigma22 - sigma11) (deviator)"},
                       {s + col("sigma11"), s + "sigma11 (lateral, held)"}};
        axes.yLabel = "stress [Pa]" + compression;
    } else if (type_ == "simpleShear") {
        axes.xExpression = "2*" + col("eps12");
        axes.xLabel = "gamma = 2 eps12 [-]";
        axes.curves = {{col("sigma12"), "sigma12"}, {col("sigma11"), "sigma11"}, {col("sigma22"), "sigma22"}};
        axes.yLabel = "stress [Pa]";
    } else if (type_ == "rotation") {
        axes.xExpression = col("step") + "*" + number(-omega_ * 180.0 / M_PI / steps_);
        axes.xLabel = "angle turned (anticlockwise) [deg]";
        axes.curves = {{col("sigma11"), "sigma11"}, {col("sigma22"), "sigma22"}, {col("sigma12"), "sigma12"}, {col("sigma33"), "sigma33"}};
        axes.yLabel = "stress [Pa]";
    } else {
        axes.xExpression = col("step");
        axes.xLabel = "step";
        axes.curves = {{col("sigma11"), "sigma11"}, {col("sigma22"), "sigma22"}, {col("sigma33"), "sigma33"}, {col("sigma12"), "sigma12"}};
        axes.yLabel = "stress [Pa]";
    }
    return axes;
}

template class LoadPath<2>;
template int csvColumn<2>(const std::string&);
#if GPIC_WITH_3D
template class LoadPath<3>;
template int csvColumn<3>(const std::string&);
#endif

} // namespace gpic
