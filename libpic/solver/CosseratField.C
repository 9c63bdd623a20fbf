#include "solver/CosseratField.H"

#include "boundaryConditions/BoundaryCondition.H"
#include "dictionary/Dictionary.H"

namespace gpic {

void CosseratField::allocate(int nNodes)
{
    const auto n = static_cast<std::size_t>(nNodes);
    inertia.assign(n, 0.0);
    momentum.assign(n, 0.0);
    rate.assign(n, 0.0);
    moment.assign(n, 0.0);
    accel.assign(n, 0.0);
    fixed.assign(n, 0);
}

std::array<bool, PlaneSpace::nFaces> readRotationSides(const Dictionary& gridDict, const std::array<bool, PlaneSpace::nFaces>& mirror)
{
    std::array<bool, PlaneSpace::nFaces> fixed{};
    const Dictionary& sides = gridDict.subDict("boundaries");
    for (int s = 0; s < 4; ++s) {
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
