#include "materials/Material.H"

#include "dictionary/Dictionary.H"

namespace gpic {

namespace {
std::string lastComponent(const std::string& path)
{
    const auto slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}
} // namespace

template <int D>
Material<D>::Material(const Dictionary& dict)
    : name_(lastComponent(dict.name())),
      rho_(dict.getChecked<double>("rho", [](const double& v) { return v > 0; }, "rho > 0"))
{}

template <int D> void Material<D>::declareFields(Particles<D>& p) const
{
    for (const auto& h : historyNames()) p.declareHistory(h);
    for (FieldGroup g : particleFields()) p.carry(g);
}

template <int D> std::unique_ptr<Material<D>> Material<D>::New(const Dictionary& dict)
{
    return Registry<Material<D>>::select(dict, dict);
}

template class Material<2>;
#if GPIC_WITH_3D
template class Material<3>;
#endif

} // namespace gpic
