#include "case/CaseInitialiser.H"

#include "bodies/BodyFiller.H"
#include "case/CaseFiles.H"
#include "core/error.H"
#include "core/Plugins.H"
#include "io/ParticlesVtk.H"
#include "io/PvdCollection.H"
#include "io/TimeDirectories.H"

namespace gpic {

InitialiseSummary initialiseCase(const std::string& dir, bool overwrite)
{
    const Dictionary control = readCaseFile(dir, "system/controlDict");
    Plugins::open(control, "libs");
    const double t0 = control.getOrDefault<double>("startTime", 0.0);
    const std::string start = timeName(t0);
    const Dictionary gridDict = readCaseFile(dir, "constant/grid");
    const Grid<2> grid(gridDict);
    // Only checked here: a bad side type fails now, not in picSolver.
    const auto boundaries = readBoundaries(gridDict);
    const Dictionary materialsDict = readCaseFile(dir, "constant/materials");
    const auto materials = readMaterials(materialsDict);
    for (const auto& m : materials)  // a polar scene: the sides' `rotation` keywords, checked here too
        if (m->needsRotation()) {
            readRotationSides(gridDict, mirrorSides(boundaries));
            break;
        }
    const Dictionary bodiesDict = readCaseFile(dir, "constant/bodies");
    auto filled = fillBodies(bodiesDict, grid, materials, readGravity(dir));
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

} // namespace gpic
