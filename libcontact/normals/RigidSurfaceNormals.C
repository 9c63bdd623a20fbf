#include "normals/RigidSurfaceNormals.H"

#include "case/CaseFiles.H"

namespace gpic {

RigidSurfaceNormals::RigidSurfaceNormals(const Dictionary& dict, const ContactScene& scene)
    : MassGradientNormals(dict, scene), surfaces_(scene.bodyNames.size())
{
    const Dictionary bodies = readCaseFile(scene.caseDir, "constant/bodies");
    for (std::size_t b = 0; b < scene.bodyNames.size(); ++b) {
        if (!scene.rigid[b]) continue;
        if (!bodies.isDict(scene.bodyNames[b]))
            dict.fail("normals", "rigidSurface needs the shape of rigid body '" + scene.bodyNames[b] +
                                     "', which constant/bodies does not define");
        surfaces_[b] = std::make_unique<RigidSurface>(bodies.subDict(scene.bodyNames[b]).subDict("shape"));
    }
}

void RigidSurfaceNormals::place(const Grid<2>& grid, const Particles<2>& p, const std::vector<int>& nodes)
{
    MassGradientNormals::place(grid, p, nodes);
    for (std::size_t b = 0; b < surfaces_.size(); ++b)
        if (surfaces_[b]) surfaces_[b]->place(p, static_cast<int>(b));
}

bool RigidSurfaceNormals::acts(int r, int /*n*/, const Vector2& x) const
{
    return !surfaces_[r] || surfaces_[r]->facesNode(x);
}

Vector2 RigidSurfaceNormals::towardsRigid(int b, int r, int n, const Vector2& x) const
{
    if (!surfaces_[r]) return MassGradientNormals::towardsRigid(b, r, n, x);
    return -surfaces_[r]->outwardNormal(x, outward(b, n));
}

GPIC_REGISTER(ContactNormals<2>, RigidSurfaceNormals, "rigidSurface")

} // namespace gpic
