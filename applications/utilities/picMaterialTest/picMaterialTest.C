// picMaterialTest: runs one material point along prescribed strain (or mixed strain and
// stress) paths, to calibrate and check a material without a simulation. It calls the
// material's updateStress on a single particle exactly as picSolver does, so every model,
// plugins from `libs` included, behaves as in a run. Reads system/materialTestDict:
//
//     material      sand;              // from constant/materials, or { type ...; rho ...; }
//     initialStress (0 0 0 0);         // sigma11 sigma22 sigma33 sigma12 [Pa], tension positive
//     geometry      planeStrain;       // or threeD: every stress and strain component, the
//                                      // 3D model (initialStress then has six: ... s12 s23 s13)
//     tests
//     {
//         oedometer { path oedometer; strain -0.03; steps 3000; }
//         biaxial   { path biaxial; strain -0.05; confining 100e3; steps 5000; }
//     }
//
// A test may override material, initialStress, deltaT, tolerance and maxIterations; see
// LoadPath.H for the paths and doc/picMaterialTest.md for the whole dictionary. Each test
// writes postProcessing/picMaterialTest/<test>.csv and <test>.png.
#include "applicationMain.H"

#include "LoadPath.H"
#include "MaterialPoint.H"
#include "PathPlot.H"
#include "PointHistoryFile.H"
#include "StepSolver.H"

#include "case/CaseFiles.H"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

namespace {

using namespace gpic;
namespace fs = std::filesystem;

//- One test, read and checked before any runs.
template <int D> struct TestSetup {
    std::string name;
    std::shared_ptr<const Material<D>> material;
    LoadPath<D> path;
    typename Space<D>::SymTensor startStress;
    double deltaT;
    double tolerance;
    int maxIterations;
};

//- The dictionary that holds `key` for this test: the test's own entry overrides the top level.
const Dictionary& holder(const Dictionary& test, const Dictionary& top, const std::string& key)
{
    return test.found(key) ? test : top;
}

//- The materials named so far, built once each, and constant/materials once it is read.
template <int D> struct MaterialLibrary {
    std::optional<Dictionary> file;
    std::map<std::string, std::shared_ptr<const Material<D>>> byName;
};

template <int D>
std::shared_ptr<const Material<D>> selectMaterial(const Dictionary& dict, const std::string& caseDir,
                                                  MaterialLibrary<D>& library)
{
    if (!dict.found("material"))
        dict.fail("material", "keyword 'material' is undefined in dictionary " + dict.name() +
                                  "; give a name from constant/materials or { type ...; }");
    if (dict.isDict("material")) return Material<D>::New(dict.subDict("material"));
    const std::string name = dict.get<std::string>("material");
    if (library.byName.count(name)) return library.byName[name];
    if (!library.file) library.file = readCaseFile(caseDir, "constant/materials");
    const Dictionary& materials = *library.file;
    if (!materials.isDict(name)) {
        std::string valid;
        for (const auto& key : materials.keys())
            if (materials.isDict(key)) valid += (valid.empty() ? "" : ", ") + key;
        dict.fail("material", "material '" + name + "' is not in constant/materials; valid choices: " +
                                  valid);
    }
    std::shared_ptr<const Material<D>> material = Material<D>::New(materials.subDict(name));
    materials.subDict(name).warnUnused();
    return library.byName[name] = material;
}

template <class T>
T optionalChecked(const Dictionary& dict, const std::string& key, const T& deflt,
                  const std::function<bool(const T&)>& valid, const std::string& requirement)
{
    return dict.found(key) ? dict.getChecked<T>(key, valid, requirement) : deflt;
}

template <int D> typename Space<D>::SymTensor readStress(const Dictionary& dict, const std::string& key)
{
    const auto v = dict.get<std::vector<double>>(key);
    bool finite = v.size() == Space<D>::nSym;
    for (double x : v) finite = finite && std::isfinite(x);
    if (!finite)
        dict.fail(key, key + (D == 2 ? " needs four finite values (sigma11 sigma22 sigma33 sigma12)"
                                     : " needs six finite values (sigma11 sigma22 sigma33 sigma12 sigma23 sigma13)") +
                           " in Pa, tension positive");
    typename Space<D>::SymTensor s;
    for (int k = 0; k < Space<D>::nSym; ++k) s[k] = v[static_cast<std::size_t>(k)];
    return s;
}

template <int D>
TestSetup<D> readTest(const std::string& name, const Dictionary& test, const Dictionary& top,
                      const std::string& caseDir, MaterialLibrary<D>& library)
{
    auto material = selectMaterial<D>(holder(test, top, "material"), caseDir, library);
    LoadPath<D> path(test);
    if (D == 2 && test.found("eps33") && material->needsRotation())
        test.fail("eps33", "eps33 (an axisymmetric ring's hoop strain) is not yet available for the polar material '" +
                               material->name() + "' in test " + name);
    const Dictionary& stressHolder = holder(test, top, "initialStress");
    const typename Space<D>::SymTensor start = stressHolder.found("initialStress")
                                                   ? readStress<D>(stressHolder, "initialStress")
                                                   : path.defaultStartStress();
    const double deltaT = optionalChecked<double>(
        holder(test, top, "deltaT"), "deltaT", 1.0, [](const double& v) { return v > 0 && std::isfinite(v); },
        "deltaT > 0 (s; seen by rate-dependent models only)");
    const double tolerance = optionalChecked<double>(
        holder(test, top, "tolerance"), "tolerance", 1e-10,
        [](const double& v) { return v > 0 && v <= 1e-3; }, "0 < tolerance <= 1e-3 (relative stress error)");
    const int maxIterations = optionalChecked<int>(holder(test, top, "maxIterations"), "maxIterations", 50,
                                                   [](const int& v) { return v >= 1; }, "maxIterations >= 1");
    return {name, std::move(material), std::move(path), start, deltaT, tolerance, maxIterations};
}

template <class SymTensor> std::string tensorText(const SymTensor& s)
{
    std::ostringstream out;
    out.precision(6);
    out << '(' << s[0];
    for (int k = 1; k < SymTensor::SizeAtCompileTime; ++k) out << ' ' << s[k];
    out << ')';
    return out.str();
}

template <int D> void runTest(const TestSetup<D>& setup, const fs::path& outputDir)
{
    const std::string csvPath = (outputDir / (setup.name + ".csv")).string();
    const std::string pngPath = (outputDir / (setup.name + ".png")).string();
    const auto start = std::chrono::steady_clock::now();

    MaterialPoint<D> point(*setup.material, setup.startStress);
    StepSolver<D> solver(setup.tolerance, setup.maxIterations);
    PointHistoryFile<D> csv(csvPath, point);
    csv.write(0, point);
    int mostIterations = 0;
    for (int n = 1; n <= setup.path.steps(); ++n) {
        const std::string where = "test '" + setup.name + "', step " + std::to_string(n) + ": ";
        try {
            mostIterations = std::max(
                mostIterations, solver.advance(point, setup.path.step(n, setup.startStress), setup.deltaT));
        } catch (const RunError& e) {
            throw RunError(where + e.what());
        }
        if (!point.sigma().allFinite())
            throw RunError(where + "material '" + setup.material->name() + "' returned a non-finite stress " +
                           tensorText(point.sigma()));
        csv.write(n, point);
    }
    csv.close();
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    std::ostringstream line;
    line.precision(6);
    line << setup.name << " (" << setup.material->name() << ", " << setup.path.type() << ", "
         << setup.path.steps() << " steps): sigma = " << tensorText(point.sigma()) << " Pa, p = " << point.p()
         << " Pa, q = " << point.q() << " Pa";
    if (setup.path.hasStressControl()) line << ", at most " << mostIterations << " iterations a step";
    line.precision(3);
    line << ", wall " << wall << " s";
    std::cout << line.str() << '\n';

    const std::string title = "picMaterialTest: " + setup.name + " (material " + setup.material->name() +
                              ", " + setup.path.type() + " path, " + std::to_string(setup.path.steps()) +
                              " steps)";
    const bool plotted = plotPath(csvPath, pngPath, title, setup.path.naturalAxes(), setup.path.steps());
    std::cout << "    wrote " << csvPath << (plotted ? ", " + pngPath : std::string()) << '\n';
}

template <int D> void runTests(const std::string& caseDir, const std::string& dictPath, const Dictionary& dict)
{
    const Dictionary& tests = dict.subDict("tests");
    MaterialLibrary<D> library;
    std::vector<TestSetup<D>> setups;
    for (const auto& name : tests.keys()) {
        if (!tests.isDict(name))
            tests.fail(name, "'" + name + "' is not a test sub-dictionary { path " +
                                 "oedometer|biaxial|simpleShear|rotation|general; ... }");
        setups.push_back(readTest<D>(name, tests.subDict(name), dict, caseDir, library));
    }
    if (setups.empty()) tests.fail("", "no test is defined in " + tests.name());
    dict.warnUnused();

    const fs::path outputDir = fs::path(caseDir) / "postProcessing" / "picMaterialTest";
    std::error_code ec;
    fs::create_directories(outputDir, ec);
    if (ec) throw RunError("cannot create " + outputDir.string() + ": " + ec.message());
    std::cout << "picMaterialTest: " << setups.size() << " test(s) from " << dictPath << '\n';
    for (const auto& setup : setups) runTest(setup, outputDir);
}

void run(const std::string& caseDir, const std::string& dictPath)
{
    const Dictionary dict = readCaseFile(caseDir, dictPath);
    Plugins::open(dict, "libs");
    // planeStrain: the plane model (eps33 = 0, or an axisymmetric ring's imposed hoop strain);
    // threeD: the 3D model, every component.
    if (dict.getWordOrDefault("geometry", {"planeStrain", "threeD"}, "planeStrain") == "threeD") {
#if GPIC_WITH_3D
        runTests<3>(caseDir, dictPath, dict);
        return;
#else
        dict.fail("geometry", "geometry threeD needs the 3D engine, and this build has the plane engine only "
                              "(configured with GPIC_DIMENSIONS 2)");
#endif
    }
    runTests<2>(caseDir, dictPath, dict);
}

} // namespace

int main(int argc, char** argv)
{
    namespace po = boost::program_options;
    po::options_description options("picMaterialTest options");
    options.add_options()("dict", po::value<std::string>()->default_value("system/materialTestDict"),
                          "test dictionary, relative to the case");
    return gpic::applicationMain(
        argc, argv,
        "picMaterialTest: drive one material point along strain paths (oedometer, biaxial, simple "
        "shear, rotation, general) and write its stress history",
        options, [](const po::variables_map& vm) {
            run(vm["case"].as<std::string>(), vm["dict"].as<std::string>());
        });
}
