#include "case/CaseInitialiser.H"

#include "bodies/BodyFiller.H"
#include "case/CaseFiles.H"
#include "core/CaseLock.H"
#include "core/error.H"
#include "core/Plugins.H"
#include "io/ParticlesVtk.H"
#include "io/PvdCollection.H"
#include "io/TimeDirectories.H"

namespace gpic {

namespace {

template <int D>
InitialiseSummary initialise(const std::string& dir, bool overwrite, const Dictionary& control, Dictionary gridDict)
{
    const double t0 = control.getOrDefault<double>("startTime", 0.0);
    const std::string start = timeName(t0);
    const Grid<D> grid(gridDict);
    // Only checked here: a bad side type fails now, not in picSolver.
    const auto boundaries = readBoundaries<D>(gridDict);
    const Dictionary materialsDict = readCaseFile(dir, "constant/materials");
    const auto materials = readMaterials<D>(materialsDict);
    if constexpr (D == 2)
        for (const auto& m : materials)  // a polar scene: the sides' `rotation` keywords, checked here too
            if (m->needsRotation()) {
                readRotationSides(gridDict, mirrorSides(boundaries));
                break;
            }
    const Dictionary bodiesDict = readCaseFile(dir, "constant/bodies");
    std::array<bool, Space<D>::nFaces> mirror{};
    for (int side = 0; side < Space<D>::nFaces; ++side) mirror[side] = boundaries[side]->isMirror();
    auto filled = fillBodies<D>(bodiesDict, grid, materials, readGravity<D>(dir), mirror);
    // The arrays the materials declare, so that the first time directory holds what every
    // later one does (ParaView colours by yieldState from the start).
    for (const auto& m : materials) m->declareFields(filled.particles);
    gridDict.warnUnused();
    materialsDict.warnUnused();
    bodiesDict.warnUnused();

    // After every input is read and checked (its errors come first), before anything is
    // written: a refusal leaves the case as it was.
    std::vector<std::string> stale;
    for (const auto& [t, name] : listTimeDirectories(dir))
        if (name != start) stale.push_back(name);
    if (!stale.empty() && !overwrite) {
        std::string names;
        for (const auto& name : stale) names += (names.empty() ? "" : ", ") + name;
        throw InputError(dir, 0, "the case already holds the time directories " + names +
                                     " of an earlier run: a new start beside them would be continued from "
                                     "them; remove them (./Allclean) or run picInit -overwrite");
    }
    for (const auto& name : stale) removeTimeDirectory(dir, name);
    writeTimeDirectoryAtomically(dir, start, [&](const std::string& tmp) {
        writeParticles(tmp + "/particles.vtp", filled.particles, t0, materialNames(materials),
                       filled.bodyNames);
    });
    // A fresh start: the ParaView index holds the initial state only.
    PvdCollection pvd(pvdPath(dir));
    pvd.removeAfter(-1e300);
    pvd.add(t0, start + "/particles.vtp", 0);
    pvd.write();
    return {filled.particles.size(), filled.bodyNames.size(), start};
}

} // namespace

InitialiseSummary initialiseCase(const std::string& dir, bool overwrite)
{
    const Dictionary control = readCaseFile(dir, "system/controlDict");
    const CaseLock lock(dir, "picInit");  // never beside a run of the case
    Plugins::open(control, "libs");
    Dictionary gridDict = readCaseFile(dir, "constant/grid");
    if (caseDimension(gridDict) == 3) {
#if GPIC_WITH_3D
        return initialise<3>(dir, overwrite, control, std::move(gridDict));
#else
        refusePlaneBuild(gridDict);
#endif
    }
    return initialise<2>(dir, overwrite, control, std::move(gridDict));
}

} // namespace gpic
