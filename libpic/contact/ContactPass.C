#include "contact/ContactPass.H"

#include "core/Threads.H"

namespace gpic {

ContactPass::ContactPass(int nBodies, const Grid& grid) : fields_(static_cast<std::size_t>(nBodies))
{
    const auto nodes = static_cast<std::size_t>(grid.nNodes());
    for (auto& f : fields_) {
        f.mass.assign(nodes, 0.0);
        f.momentum.assign(nodes, Vector2::Zero());
        f.velocity.assign(nodes, Vector2::Zero());
        f.force.assign(nodes, Vector2::Zero());
        f.accel.assign(nodes, Vector2::Zero());
    }
}

void ContactPass::reset(const std::vector<int>& active)
{
    // Every step, before the scatter: threaded as Grid::resetFields, all bodies in one loop
    // (a parallel region each would cost more than the zeroing), with the arrays' pointers
    // in locals, which no store can alias.
    struct Arrays {
        double* mass;
        Vector2* vectors[4];
    };
    std::vector<Arrays> bodyArrays;
    for (BodyField& f : fields_)
        bodyArrays.push_back({f.mass.data(), {f.momentum.data(), f.velocity.data(), f.force.data(), f.accel.data()}});
    const Arrays* arrays = bodyArrays.data();
    const int* nodes = active.data();
    const int bodies = nBodies();
    parallelFor(static_cast<long>(active.size()), [=](long k) {
        const int n = nodes[k];
        for (int b = 0; b < bodies; ++b) {
            arrays[b].mass[n] = 0.0;
            for (Vector2* field : arrays[b].vectors) field[n].setZero();
        }
    });
}

std::unique_ptr<ContactPass> ContactPass::New(const Dictionary& dict, const ContactScene& scene, const Grid& grid)
{
    ContactParts parts;
    parts.law = ContactLaw::New(dict, scene.bodyNames);
    parts.normalsName = ContactNormals::typeName(dict);
    parts.normals = ContactNormals::New(dict, scene);
    parts.nBodies = scene.nBodies();
    parts.grid = &grid;
    if (!parts.law->needsBodyFields() || parts.nBodies < 2) return nullptr;
    // One algorithm is built in; `algorithm` names another from a user's library.
    const std::string algorithm = dict.found("algorithm") ? dict.get<std::string>("algorithm") : "multiField";
    return Registry<ContactPass>::select(algorithm, dict, dict, parts, "algorithm");
}

} // namespace gpic
