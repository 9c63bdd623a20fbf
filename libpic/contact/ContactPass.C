#include "contact/ContactPass.H"

#include "core/Threads.H"

namespace gpic {

template <int D>
ContactPass<D>::ContactPass(int nBodies, const Grid<D>& grid) : fields_(static_cast<std::size_t>(nBodies))
{
    const auto nodes = static_cast<std::size_t>(grid.nNodes());
    for (auto& f : fields_) {
        f.mass.assign(nodes, 0.0);
        f.momentum.assign(nodes, Vector::Zero());
        f.velocity.assign(nodes, Vector::Zero());
        f.force.assign(nodes, Vector::Zero());
        f.accel.assign(nodes, Vector::Zero());
    }
}

template <int D> void ContactPass<D>::trackPositions()
{
    tracksPositions_ = true;
    for (auto& f : fields_) f.position.assign(f.mass.size(), Vector::Zero());
}

template <int D>
void ContactPass<D>::reset(const std::vector<int>& active)
{
    // Every step, before the scatter: threaded as Grid::resetFields, all bodies in one loop
    // (a parallel region each would cost more than the zeroing), with the arrays' pointers
    // in locals, which no store can alias.
    struct Arrays {
        double* mass;
        Vector* vectors[4];
    };
    std::vector<Arrays> bodyArrays;
    for (BodyField<D>& f : fields_)
        bodyArrays.push_back({f.mass.data(), {f.momentum.data(), f.velocity.data(), f.force.data(), f.accel.data()}});
    if (tracksPositions_)  // a fifth array only where it is kept: the zeroing of the others unchanged
        for (BodyField<D>& f : fields_) {
            Vector* position = f.position.data();
            parallelFor(static_cast<long>(active.size()), [=, nodes = active.data()](long k) { position[nodes[k]].setZero(); });
        }
    const Arrays* arrays = bodyArrays.data();
    const int* nodes = active.data();
    const int bodies = nBodies();
    parallelFor(static_cast<long>(active.size()), [=](long k) {
        const int n = nodes[k];
        for (int b = 0; b < bodies; ++b) {
            arrays[b].mass[n] = 0.0;
            for (Vector* field : arrays[b].vectors) field[n].setZero();
        }
    });
}

template <int D>
std::unique_ptr<ContactPass<D>> ContactPass<D>::New(const Dictionary& dict, const ContactScene& scene, const Grid<D>& grid)
{
    ContactParts<D> parts;
    parts.law = ContactLaw<D>::New(dict, scene.bodyNames);
    parts.normalsName = ContactNormals<D>::typeName(dict);
    parts.normals = ContactNormals<D>::New(dict, scene);
    parts.nBodies = scene.nBodies();
    parts.grid = &grid;
    parts.ranks = scene.ranks;
    if (!parts.law->needsBodyFields() || parts.nBodies < 2) return nullptr;
    // One algorithm is built in; `algorithm` names another from a user's library.
    const std::string algorithm = dict.found("algorithm") ? dict.get<std::string>("algorithm") : "multiField";
    return Registry<ContactPass<D>>::select(algorithm, dict, dict, parts, "algorithm");
}

template class ContactPass<2>;
#if GPIC_WITH_3D
template class ContactPass<3>;
#endif

} // namespace gpic
