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
} // namespace

int main(int argc, char** argv)
{
    boost::program_options::options_description options("picToC options");
    return gpic::applicationMain(argc, argv, "picToC: list the run-time selectable types", options,
                                 [](const auto&) {
                                     list<gpic::Material<2>>();
                                     list<gpic::BoundaryCondition<2>>();
                                     list<gpic::ContactLaw<2>>();
                                     list<gpic::ContactNormals<2>>();
                                     list<gpic::ContactPass<2>>();
                                     list<gpic::ShapeFunction<2>>();
                                     list<gpic::UpdateScheme>();
                                     list<gpic::ParticleTransfer>();
                                     list<gpic::FunctionObject>();
                                     list<gpic::Shape>();
                                     list<gpic::RigidBodyDriver<2>>();
                                     list<gpic::ParticleLoad<2>>();
                                     list<gpic::Stage>();
                                 });
}
