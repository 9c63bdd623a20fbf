#include "coupling/GridCoupling.H"

#include "core/Registry.H"
#include "core/error.H"
#include "engine/EnginePass.H"

namespace gpic {

GridCoupling::GridCoupling(CouplingParts& parts) : contact_(std::move(parts.contact)), bodies_(contact_.get()) {}

std::unique_ptr<GridCoupling> GridCoupling::New(CouplingParts& parts)
{
    const bool anyRigid = parts.rigid && !parts.rigid->empty();
    const std::string type = parts.contact ? "multiField" : (anyRigid ? "singleFieldRigidBodies" : "singleField");
    auto& table = Registry<GridCoupling>::table();
    const auto it = table.find(type);
    if (it == table.end())
        throw RunError("grid coupling '" + type + "' is not registered (contact needs libcontact); registered: " +
                       Registry<GridCoupling>::validChoices());
    return it->second.factory(parts);
}

void GridCoupling::attach(Grid& grid, const Drivers& rigid)
{
    const auto nodes = static_cast<std::size_t>(grid.nNodes());
    grid.fContact.assign(!rigid.empty() || bodies_ ? nodes : 0, Vector2::Zero());
    loads_.assign(bodies_ ? static_cast<std::size_t>(bodies_->nBodies()) : rigid.size(), RigidBodyLoad{});
}

void GridCoupling::constrainFiltered(EngineView& e, int, std::vector<Vector2>& w, double) const
{
    e.sides.constrain(w);
}

void GridCoupling::forEachRigidNode(const Grid&, const Drivers&, const std::function<void(int, int)>&) const {}

} // namespace gpic
