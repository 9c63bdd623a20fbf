#include "normals/RigidSurfaceNormals.H"

#include "case/CaseFiles.H"

namespace gpic {

template <int D>
RigidSurfaceNormals<D>::RigidSurfaceNormals(const Dictionary& dict, const ContactScene& scene)
    : MassGradientNormals<D>(dict, scene), surfaces_(scene.bodyNames.size()), ranks_(scene.ranks)
{
    const Dictionary bodies = readCaseFile(scene.caseDir, "constant/bodies");
    for (std::size_t b = 0; b < scene.bodyNames.size(); ++b) {
        if (!scene.rigid[b]) continue;
        if (!bodies.isDict(scene.bodyNames[b]))
            dict.fail("normals", "rigidSurface needs the shape of rigid body '" + scene.bodyNames[b] +
                                     "', which constant/bodies does not define");
        surfaces_[b] = std::make_unique<Surface>(bodies.subDict(scene.bodyNames[b]).subDict("shape"));
    }
}

template <int D>
void RigidSurfaceNormals<D>::place(const Grid<D>& grid, const Particles<D>& p, const std::vector<int>& nodes)
{
    MassGradientNormals<D>::place(grid, p, nodes);
    for (std::size_t b = 0; b < surfaces_.size(); ++b) {
        if (!surfaces_[b]) continue;
        if constexpr (D == 2) surfaces_[b]->place(p, static_cast<int>(b), ranks_);
        else surfaces_[b]->place(p, static_cast<int>(b), grid.cellSize().maxCoeff(), grid.origin(), grid.upper(), ranks_);
    }
}

template <int D> bool RigidSurfaceNormals<D>::acts(int r, int n, const Vector& x) const
{
    if (!surfaces_[r]) return true;
    if constexpr (D == 2) return surfaces_[r]->facesNode(x);
    else return surfaces_[r]->facesNode(n, x);
}

template <int D>
typename RigidSurfaceNormals<D>::Vector RigidSurfaceNormals<D>::towardsRigid(int b, int r, int n, const Vector& x) const
{
    if (!surfaces_[r]) return MassGradientNormals<D>::towardsRigid(b, r, n, x);
    if constexpr (D == 2) return -surfaces_[r]->outwardNormal(x, this->outward(b, n));
    else return -surfaces_[r]->outwardNormal(x, this->outward(b, n), n);
}

template class RigidSurfaceNormals<2>;
#if GPIC_WITH_3D
template class RigidSurfaceNormals<3>;
#endif

GPIC_REGISTER_DIMS(ContactNormals, RigidSurfaceNormals, "rigidSurface")

} // namespace gpic
