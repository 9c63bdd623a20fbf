// picToC: lists every run-time selectable type by kind (like OpenFOAM's foamToC), after
// loading any libraries given with -libs. A type that a library other than the project's
// own registered is followed by that library's file name in brackets.
#include "applicationMain.H"
#include "bodies/RigidBodyDriver.H"
#include "bodies/Shape.H"
#include "boundaryConditions/BoundaryCondition.H"
#include "contact/ContactLaw.H"
#include "contact/ContactNormals.H"
#include "contact/ContactPass.H"
#include "core/Plugins.H"
#include "functionObjects/FunctionObject.H"
#include "loads/ParticleLoad.H"
#include "materials/Material.H"
#include "schemes/ParticleTransfer.H"
#include "schemes/UpdateScheme.H"
#include "shapeFunctions/ShapeFunction.H"
#include "stages/Stage.H"

#include <filesystem>
#include <iostream>
#include <set>

namespace {
namespace fs = std::filesystem;

//- Is `library` one of the project's own: libpic, or a model library beside it?
bool projectLibrary(const std::string& library)
{
    static const fs::path ownDirectory =
        fs::path(gpic::Plugins::libraryOf(reinterpret_cast<const void*>(&gpic::Plugins::libraryOf))).parent_path();
    static const std::set<std::string> own{"libpic.so", "libmaterials.so", "libcontact.so"};
    const fs::path path(library);
    return path.parent_path() == ownDirectory && own.count(path.filename().string()) > 0;
}

template <class Base> void list()
{
    std::string line;
    for (const auto& [name, entry] : gpic::Registry<Base>::table()) {
        line += (line.empty() ? "" : ", ") + name;
        if (!projectLibrary(entry.library)) line += " [" + fs::path(entry.library).filename().string() + "]";
    }
    std::cout << Base::kindName << ": " << (line.empty() ? "(none)" : line) << '\n';
}

//- A kind templated on the dimension: every name, marked where it serves one dimension only.
template <template <int> class Kind> void listDims()
{
    std::set<std::string> names;
    for (const auto& [name, entry] : gpic::Registry<Kind<2>>::table()) names.insert(name);
    for (const auto& [name, entry] : gpic::Registry<Kind<3>>::table()) names.insert(name);
    std::string line;
    for (const std::string& name : names) {
        const auto plane = gpic::Registry<Kind<2>>::table().find(name);
        const auto solid = gpic::Registry<Kind<3>>::table().find(name);
        const std::string& library = plane != gpic::Registry<Kind<2>>::table().end() ? plane->second.library
                                                                                      : solid->second.library;
        line += (line.empty() ? "" : ", ") + name;
        if (!projectLibrary(library)) line += " [" + fs::path(library).filename().string() + "]";
        if (solid == gpic::Registry<Kind<3>>::table().end()) line += " (2D)";
        else if (plane == gpic::Registry<Kind<2>>::table().end()) line += " (3D)";
    }
    std::cout << Kind<2>::kindName << ": " << (line.empty() ? "(none)" : line) << '\n';
}
} // namespace

int main(int argc, char** argv)
{
    boost::program_options::options_description options("picToC options");
    return gpic::applicationMain(argc, argv, "picToC: list the run-time selectable types ((2D): plane scenes only, (3D): 3D only)", options,
                                 [](const auto&) {
                                     listDims<gpic::Material>();
                                     listDims<gpic::BoundaryCondition>();
                                     listDims<gpic::ContactLaw>();
                                     listDims<gpic::ContactNormals>();
                                     listDims<gpic::ContactPass>();
                                     listDims<gpic::ShapeFunction>();
                                     list<gpic::UpdateScheme>();
                                     list<gpic::ParticleTransfer>();
                                     listDims<gpic::FunctionObject>();
                                     listDims<gpic::Shape>();
                                     listDims<gpic::RigidBodyDriver>();
                                     listDims<gpic::ParticleLoad>();
                                     listDims<gpic::Stage>();
                                 });
}
