#include "LoadPath.H"

#include "dictionary/Dictionary.H"

#include <cmath>
#include <sstream>

namespace gpic {

namespace {

const char* const componentNames[3] = {"11", "22", "12"};

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

const std::vector<std::string>& LoadPath::pathNames()
{
    static const std::vector<std::string> names{"oedometer", "biaxial", "simpleShear", "rotation",
                                                "general"};
    return names;
}

LoadPath::LoadPath(const Dictionary& dict)
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

void LoadPath::readGeneral(const Dictionary& dict)
{
    for (int c = 0; c < 3; ++c) {
        const std::string epsKey = std::string("eps") + componentNames[c];
        const std::string sigmaKey = std::string("sigma") + componentNames[c];
        const int k = controlledComponents[c];
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
    if (dict.found("eps33")) strain_[ZZ] = readStrain(dict, "eps33");
    if (dict.found("angle"))
        omega_ = spinOfRotation(readFinite(dict, "angle", "angle in degrees (anticlockwise)"));
}

SymTensor LoadPath::defaultStartStress() const
{
    if (type_ != "biaxial") return SymTensor::Zero();
    const double p = sigmaEnd_[XX];
    return SymTensor(p, p, p, 0.0);
}

bool LoadPath::hasStressControl() const
{
    return stressControlled_[0] || stressControlled_[1] || stressControlled_[2];
}

StepControl LoadPath::step(int n, const SymTensor& startStress) const
{
    StepControl control;
    control.dEps = strain_ / steps_;
    control.dOmega = omega_ / steps_;
    control.stressControlled = stressControlled_;
    const double fraction = static_cast<double>(n) / steps_;
    for (int c = 0; c < 3; ++c) {
        if (!stressControlled_[c]) continue;
        const int k = controlledComponents[c];
        control.dEps[k] = 0;
        control.sigmaTarget[k] =
            held_ ? sigmaEnd_[k] : startStress[k] + fraction * (sigmaEnd_[k] - startStress[k]);
    }
    return control;
}

NaturalAxes LoadPath::naturalAxes() const
{
    NaturalAxes axes;
    const std::string s = axialSign_ < 0 ? "-" : "";
    const std::string compression = axialSign_ < 0 ? ", compression positive" : "";
    if (type_ == "oedometer") {
        axes.xExpression = s + "$3";
        axes.xLabel = s + "eps22 [-]";
        axes.curves = {{s + "$6", s + "sigma22"}, {s + "$5", s + "sigma11"}, {s + "$7", s + "sigma33"}};
        axes.yLabel = "stress [Pa]" + compression;
    } else if (type_ == "biaxial") {
        axes.xExpression = s + "$3";
        axes.xLabel = s + "eps22 (axial strain) [-]";
        axes.curves = {{s + "($6-$5)", s + "(sigma22 - sigma11) (deviator)"},
                       {s + "$5", s + "sigma11 (lateral, held)"}};
        axes.yLabel = "stress [Pa]" + compression;
    } else if (type_ == "simpleShear") {
        axes.xExpression = "2*$4";
        axes.xLabel = "gamma = 2 eps12 [-]";
        axes.curves = {{"$8", "sigma12"}, {"$5", "sigma11"}, {"$6", "sigma22"}};
        axes.yLabel = "stress [Pa]";
    } else if (type_ == "rotation") {
        axes.xExpression = "$1*" + number(-omega_ * 180.0 / M_PI / steps_);
        axes.xLabel = "angle turned (anticlockwise) [deg]";
        axes.curves = {{"$5", "sigma11"}, {"$6", "sigma22"}, {"$8", "sigma12"}, {"$7", "sigma33"}};
        axes.yLabel = "stress [Pa]";
    } else {
        axes.xExpression = "$1";
        axes.xLabel = "step";
        axes.curves = {{"$5", "sigma11"}, {"$6", "sigma22"}, {"$7", "sigma33"}, {"$8", "sigma12"}};
        axes.yLabel = "stress [Pa]";
    }
    return axes;
}

} // namespace gpic
