#include "coupling/GridCoupling.H"

#include "core/Registry.H"
#include "core/error.H"
#include "engine/EnginePass.H"

namespace gpic {

template <int D>
GridCoupling<D>::GridCoupling(CouplingParts<D>& parts) : contact_(std::move(parts.contact)), bodies_(contact_.get()) {}

template <int D>
std::unique_ptr<GridCoupling<D>> GridCoupling<D>::New(CouplingParts<D>& parts)
{
    const bool anyRigid = parts.rigid && !parts.rigid->empty();
    const std::string type = parts.contact ? "multiField" : (anyRigid ? "singleFieldRigidBodies" : "singleField");
    auto& table = Registry<GridCoupling<D>>::table();
    const auto it = table.find(type);
    if (it == table.end())
        throw RunError("grid coupling '" + type + "' is not registered (contact needs libcontact); registered: " +
                       Registry<GridCoupling<D>>::validChoices());
    return it->second.factory(parts);
}

template <int D>
void GridCoupling<D>::attach(Grid<D>& grid, const Drivers& rigid)
{
    const auto nodes = static_cast<std::size_t>(grid.nNodes());
    grid.fContact.assign(!rigid.empty() || bodies_ ? nodes : 0, Vector::Zero());
    loads_.assign(bodies_ ? static_cast<std::size_t>(bodies_->nBodies()) : rigid.size(), RigidBodyLoad<D>{});
}

template <int D>
void GridCoupling<D>::constrainFiltered(EngineView<D>& e, int, std::vector<Vector>& w, double) const
{
    e.sides.constrain(w);
}

template <int D>
void GridCoupling<D>::forEachRigidNode(const Grid<D>&, const Drivers&, const std::function<void(int, int)>&) const {}

template class GridCoupling<2>;
#if GPIC_WITH_3D
template class GridCoupling<3>;
#endif

} // namespace gpic
