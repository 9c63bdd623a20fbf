#include "run/ToolSurfaces.H"

#include "case/CaseFiles.H"
#include "dictionary/Dictionary.H"
#include "bodies/RigidPose.H"
#include "io/SurfaceVtk.H"
#include "particles/Particles.H"

#include <algorithm>

#include <filesystem>

namespace gpic {

template <int D>
ToolSurfaces<D>::ToolSurfaces(const std::string& caseDir, const std::vector<std::string>& bodyNames,
                              const std::vector<bool>& rigid)
{
    if constexpr (D == 3) {
        if (std::find(rigid.begin(), rigid.end(), true) == rigid.end()) return;
        const Dictionary bodies = readCaseFile(caseDir, "constant/bodies");
        for (std::size_t b = 0; b < bodyNames.size() && b < rigid.size(); ++b) {
            if (!rigid[b] || !bodies.isDict(bodyNames[b])) continue;
            const Dictionary* shape = bodies.subDict(bodyNames[b]).subDictPtr("shape");
            if (!shape || !shape->found("type") || shape->get<std::string>("type") != "triSurface") continue;
            tools_.push_back({static_cast<int>(b), bodyNames[b], TriSurface::read(*shape)});
        }
    }
}

template <int D> std::vector<std::string> ToolSurfaces<D>::fileNames() const
{
    std::vector<std::string> names;
    for (const Tool& t : tools_) names.push_back(t.name + ".vtp");
    return names;
}

template <int D>
void ToolSurfaces<D>::write(const std::string& dir, const Particles<D>& particles, double time, const RankReductions& ranks) const
{
    if constexpr (D == 3) {
        using Vector = Space<3>::Vector;
        for (const Tool& tool : tools_) {
            const RigidPose pose = RigidPose::of(particles, tool.body, ranks);
            std::vector<Vector> corners;
            corners.reserve(tool.surface.corners().size());
            for (const Vector& v : tool.surface.corners()) corners.push_back(pose.place(v));
            writeSurface((std::filesystem::path(dir) / (tool.name + ".vtp")).string(), corners,
                         tool.surface.facets(), time);
        }
    }
}

template class ToolSurfaces<2>;
#if GPIC_WITH_3D
template class ToolSurfaces<3>;
#endif

} // namespace gpic
