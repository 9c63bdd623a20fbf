#include "contact/ContactPass.H"

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
    for (auto& f : fields_)
        for (int n : active) {
            f.mass[n] = 0.0;
            f.momentum[n].setZero();
            f.velocity[n].setZero();
            f.force[n].setZero();
            f.accel[n].setZero();
        }
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
