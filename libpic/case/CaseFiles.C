#include "case/CaseFiles.H"

#include "core/error.H"

#include <algorithm>
#include <filesystem>

namespace gpic {

Dictionary readCaseFile(const std::string& caseDir, const std::string& relativePath)
{
    return Dictionary::readFile((std::filesystem::path(caseDir) / relativePath).string(),
                                relativePath);
}

template <int D> std::vector<std::unique_ptr<Material<D>>> readMaterials(const Dictionary& materialsDict)
{
    std::vector<std::unique_ptr<Material<D>>> materials;
    materialsDict.refuseRepeats("material");
    for (const auto& key : materialsDict.keys()) {
        if (!materialsDict.isDict(key))
            materialsDict.fail(key, "'" + key + "' is not a material sub-dictionary");
        materials.push_back(Material<D>::New(materialsDict.subDict(key)));
    }
    if (materials.empty()) materialsDict.fail("", "no material is defined");
    return materials;
}

template <int D>
std::array<std::unique_ptr<BoundaryCondition<D>>, Space<D>::nFaces> readBoundaries(const Dictionary& gridDict)
{
    const Dictionary& sides = gridDict.subDict("boundaries");
    // The axis of an axisymmetric scene (the left side at r = 0): u_r = 0 there, a mirror.
    const bool leftIsAxis =
        D == 2 &&
        gridDict.getWordOrDefault("geometry", {"planeStrain", "axisymmetric"}, "planeStrain") == "axisymmetric" &&
        gridDict.get<typename Space<D>::Vector>("origin").x() == 0.0;
    const Dictionary axis = Dictionary::parse("type symmetry;", sides.name() + "/left");
    std::array<std::unique_ptr<BoundaryCondition<D>>, Space<D>::nFaces> bcs;
    for (int s = 0; s < Space<D>::nFaces; ++s) {
        const std::string& side = gridSideNames()[s];
        if (s == static_cast<int>(GridSide::left) && leftIsAxis) {
            if (!sides.found(side)) {
                bcs[s] = Registry<BoundaryCondition<D>>::select(axis, axis, GridSide::left);
                continue;
            }
            const std::string type = sides.subDict(side).get<std::string>("type");
            if (type != "symmetry" && type != "slip" && type != "fixed")
                sides.subDict(side).fail("type", "the left side is the axis r = 0 (geometry axisymmetric): it needs "
                                                 "u_r = 0, not '" + type + "'; valid choices: symmetry (the default), "
                                                 "slip, fixed");
        }
        bcs[s] = Registry<BoundaryCondition<D>>::select(sides.subDict(side), sides.subDict(side),
                                                        static_cast<GridSide>(s));
    }
    return bcs;
}

std::array<bool, PlaneSpace::nFaces> mirrorSides(const std::array<std::unique_ptr<BoundaryCondition<2>>, PlaneSpace::nFaces>& boundaries)
{
    std::array<bool, PlaneSpace::nFaces> mirror{};
    for (std::size_t s = 0; s < 4; ++s) mirror[s] = boundaries[s]->isMirror();
    return mirror;
}

template <int D>
std::vector<std::unique_ptr<RigidBodyDriver<D>>> readRigidBodies(const Dictionary& dict,
                                                                 const std::vector<std::string>& bodyNames)
{
    std::vector<std::unique_ptr<RigidBodyDriver<D>>> drivers(bodyNames.size());
    dict.refuseRepeats("rigid body");
    for (const auto& key : dict.keys()) {
        const auto it = std::find(bodyNames.begin(), bodyNames.end(), key);
        if (it == bodyNames.end()) {
            std::string valid;
            for (const auto& b : bodyNames) valid += (valid.empty() ? "" : ", ") + b;
            dict.fail(key, "'" + key + "' is not a body of the particles; valid choices: " + valid);
        }
        if (!dict.isDict(key)) dict.fail(key, "'" + key + "' needs a driver sub-dictionary { type ...; }");
        drivers[static_cast<std::size_t>(it - bodyNames.begin())] = RigidBodyDriver<D>::New(dict.subDict(key));
    }
    dict.warnUnused();
    return drivers;
}

template <int D> std::vector<std::unique_ptr<ParticleLoad<D>>> readLoads(const Dictionary& dict)
{
    std::vector<std::unique_ptr<ParticleLoad<D>>> loads;
    for (const auto& key : dict.keys()) {
        if (!dict.isDict(key)) dict.fail(key, "'" + key + "' needs a load sub-dictionary { type ...; }");
        loads.push_back(ParticleLoad<D>::New(dict.subDict(key)));
    }
    dict.warnUnused();
    return loads;
}

template <int D> typename Space<D>::Vector readGravity(const std::string& caseDir)
{
    using Vector = typename Space<D>::Vector;
    if (!std::filesystem::exists(std::filesystem::path(caseDir) / "constant/g"))
        return Vector::Zero();
    const Dictionary g = readCaseFile(caseDir, "constant/g");
    const Vector value = g.get<Vector>("value");
    g.warnUnused();
    return value;
}

std::string caseName(const std::string& caseDir)
{
    std::filesystem::path p = std::filesystem::absolute(caseDir).lexically_normal();
    if (p.filename().empty()) p = p.parent_path();
    return p.filename().string();
}

std::optional<StoredTime> readStoredTime(const std::string& caseDir, const std::string& timeName)
{
    const std::filesystem::path file = std::filesystem::path(caseDir) / timeName / "uniform/time";
    if (!std::filesystem::exists(file)) return std::nullopt;
    const Dictionary t = Dictionary::readFile(file.string(), timeName + "/uniform/time");
    return StoredTime{t.get<double>("value"), t.get<long>("index"), t.getOrDefault<double>("removedMass", 0.0)};
}

std::string pvdPath(const std::string& caseDir)
{
    namespace fs = std::filesystem;
    const fs::path own = fs::path(caseDir) / (caseName(caseDir) + ".pvd");
    if (fs::exists(own)) return own.string();
    // A case copied under another name keeps the index it came with (ParaView opens that one).
    std::vector<std::string> found;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(caseDir, ec))
        if (entry.path().extension() == ".pvd" && entry.is_regular_file(ec)) found.push_back(entry.path().filename().string());
    std::sort(found.begin(), found.end());
    if (found.size() == 1) return (fs::path(caseDir) / found.front()).string();
    if (found.size() > 1) {
        std::string list;
        for (const auto& f : found) list += (list.empty() ? "" : ", ") + f;
        throw RunError("case " + caseDir + " holds several ParaView indexes (" + list + ") and none named " +
                       own.filename().string() + ": keep the one to go on with (picListTimes -rebuild writes it afresh)");
    }
    return own.string();
}

template <int D> std::vector<std::string> materialNames(const std::vector<std::unique_ptr<Material<D>>>& materials)
{
    std::vector<std::string> names;
    for (const auto& m : materials) names.push_back(m->name());
    return names;
}

std::array<bool, PlaneSpace::nFaces> readRotationSides(const Dictionary& gridDict, const std::array<bool, PlaneSpace::nFaces>& mirror)
{
    std::array<bool, PlaneSpace::nFaces> fixed{};
    const Dictionary& sides = gridDict.subDict("boundaries");
    for (int s = 0; s < PlaneSpace::nFaces; ++s) {
        const Dictionary& side = sides.subDict(gridSideNames()[s]);
        const std::string deflt = mirror[s] ? "fixed" : "free";
        fixed[s] = side.getWordOrDefault("rotation", {"fixed", "free"}, deflt) == "fixed";
    }
    return fixed;
}

std::vector<char> readRigidRotation(const Dictionary& rigidBodies, const std::vector<std::string>& bodyNames)
{
    std::vector<char> fixed(bodyNames.size(), 1);
    for (std::size_t b = 0; b < bodyNames.size(); ++b)
        if (rigidBodies.isDict(bodyNames[b]))
            fixed[b] = rigidBodies.subDict(bodyNames[b]).getWordOrDefault("rotation", {"fixed", "free"}, "fixed") ==
                       "fixed";
    return fixed;
}

int caseDimension(const Dictionary& gridDict)
{
    // Read as a list, so that a length prefix (3(nx ny nz)) or a malformed entry is the
    // dictionary's to judge; Grid checks the counts themselves.
    const bool threeCounts = gridDict.get<std::vector<int>>("nCells").size() == 3;
    if (!gridDict.found("geometry")) return threeCounts ? 3 : 2;
    const std::string geometry = gridDict.getWord("geometry", {"planeStrain", "axisymmetric", "threeD"});
    if (geometry == "threeD") return 3;
    if (threeCounts)
        gridDict.fail("geometry", "keyword 'geometry' in dictionary " + gridDict.name() + ": geometry " + geometry +
                                      " is a plane scene (nCells (nx ny)), but nCells has three counts; a 3D grid is "
                                      "geometry threeD (the default with three counts)");
    return 2;
}

void refusePlaneBuild(const Dictionary& gridDict)
{
    gridDict.fail(gridDict.found("nCells") ? "nCells" : "geometry",
                  "constant/grid describes a 3D scene, and this build has the plane engine only (configured with "
                  "GPIC_DIMENSIONS 2): rebuild with cmake -DGPIC_DIMENSIONS=\"2;3\" (the default)");
}

#define GPIC_CASE_FILES(D)                                                                                     \
    template std::vector<std::unique_ptr<Material<D>>> readMaterials<D>(const Dictionary&);                    \
    template std::array<std::unique_ptr<BoundaryCondition<D>>, Space<D>::nFaces> readBoundaries<D>(const Dictionary&); \
    template std::vector<std::unique_ptr<RigidBodyDriver<D>>> readRigidBodies<D>(const Dictionary&,             \
                                                                                 const std::vector<std::string>&); \
    template std::vector<std::unique_ptr<ParticleLoad<D>>> readLoads<D>(const Dictionary&);                    \
    template Space<D>::Vector readGravity<D>(const std::string&);                                              \
    template std::vector<std::string> materialNames<D>(const std::vector<std::unique_ptr<Material<D>>>&);
GPIC_CASE_FILES(2)
#if GPIC_WITH_3D
GPIC_CASE_FILES(3)
#endif
#undef GPIC_CASE_FILES

} // namespace gpic
