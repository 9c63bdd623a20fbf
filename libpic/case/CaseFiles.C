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

std::vector<std::unique_ptr<Material<2>>> readMaterials(const Dictionary& materialsDict)
{
    std::vector<std::unique_ptr<Material<2>>> materials;
    for (const auto& key : materialsDict.keys()) {
        if (!materialsDict.isDict(key))
            materialsDict.fail(key, "'" + key + "' is not a material sub-dictionary");
        materials.push_back(Material<2>::New(materialsDict.subDict(key)));
    }
    if (materials.empty()) materialsDict.fail("", "no material is defined");
    return materials;
}

std::array<std::unique_ptr<BoundaryCondition<2>>, PlaneSpace::nFaces> readBoundaries(const Dictionary& gridDict)
{
    const Dictionary& sides = gridDict.subDict("boundaries");
    // The axis of an axisymmetric scene (the left side at r = 0): u_r = 0 there, a mirror.
    const bool leftIsAxis =
        gridDict.getWordOrDefault("geometry", {"planeStrain", "axisymmetric"}, "planeStrain") == "axisymmetric" &&
        gridDict.get<Vector2>("origin").x() == 0.0;
    const Dictionary axis = Dictionary::parse("type symmetry;", sides.name() + "/left");
    std::array<std::unique_ptr<BoundaryCondition<2>>, PlaneSpace::nFaces> bcs;
    for (int s = 0; s < 4; ++s) {
        const std::string& side = gridSideNames()[s];
        if (s == static_cast<int>(GridSide::left) && leftIsAxis) {
            if (!sides.found(side)) {
                bcs[s] = Registry<BoundaryCondition<2>>::select(axis, axis, GridSide::left);
                continue;
            }
            const std::string type = sides.subDict(side).get<std::string>("type");
            if (type != "symmetry" && type != "slip" && type != "fixed")
                sides.subDict(side).fail("type", "the left side is the axis r = 0 (geometry axisymmetric): it needs "
                                                 "u_r = 0, not '" + type + "'; valid choices: symmetry (the default), "
                                                 "slip, fixed");
        }
        bcs[s] = Registry<BoundaryCondition<2>>::select(sides.subDict(side), sides.subDict(side),
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

std::vector<std::unique_ptr<RigidBodyDriver<2>>> readRigidBodies(const Dictionary& dict,
                                                              const std::vector<std::string>& bodyNames)
{
    std::vector<std::unique_ptr<RigidBodyDriver<2>>> drivers(bodyNames.size());
    for (const auto& key : dict.keys()) {
        const auto it = std::find(bodyNames.begin(), bodyNames.end(), key);
        if (it == bodyNames.end()) {
            std::string valid;
            for (const auto& b : bodyNames) valid += (valid.empty() ? "" : ", ") + b;
            dict.fail(key, "'" + key + "' is not a body of the particles; valid choices: " + valid);
        }
        if (!dict.isDict(key)) dict.fail(key, "'" + key + "' needs a driver sub-dictionary { type ...; }");
        drivers[static_cast<std::size_t>(it - bodyNames.begin())] = RigidBodyDriver<2>::New(dict.subDict(key));
    }
    dict.warnUnused();
    return drivers;
}

std::vector<std::unique_ptr<ParticleLoad<2>>> readLoads(const Dictionary& dict)
{
    std::vector<std::unique_ptr<ParticleLoad<2>>> loads;
    for (const auto& key : dict.keys()) {
        if (!dict.isDict(key)) dict.fail(key, "'" + key + "' needs a load sub-dictionary { type ...; }");
        loads.push_back(ParticleLoad<2>::New(dict.subDict(key)));
    }
    dict.warnUnused();
    return loads;
}

Vector2 readGravity(const std::string& caseDir)
{
    if (!std::filesystem::exists(std::filesystem::path(caseDir) / "constant/g"))
        return Vector2::Zero();
    const Dictionary g = readCaseFile(caseDir, "constant/g");
    const Vector2 value = g.get<Vector2>("value");
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

std::vector<std::string> materialNames(const std::vector<std::unique_ptr<Material<2>>>& materials)
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

} // namespace gpic
