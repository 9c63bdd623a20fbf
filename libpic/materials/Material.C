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

Material::Material(const Dictionary& dict)
    : name_(lastComponent(dict.name())),
      rho_(dict.getChecked<double>("rho", [](const double& v) { return v > 0; }, "rho > 0"))
{}

void Material::declareFields(Particles& p) const
{
    for (const auto& h : historyNames()) p.declareHistory(h);
    for (FieldGroup g : particleFields()) p.carry(g);
}

std::unique_ptr<Material> Material::New(const Dictionary& dict)
{
    return Registry<Material>::select(dict, dict);
}

} // namespace gpic
