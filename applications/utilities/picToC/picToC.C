// picToC: lists every run-time selectable type by kind (like OpenFOAM's foamToC), after
// loading any libraries given with -libs.
#include "applicationMain.H"
#include "bodies/RigidBodyDriver.H"
#include "bodies/Shape.H"
#include "boundaryConditions/BoundaryCondition.H"
#include "contact/ContactLaw.H"
#include "functionObjects/FunctionObject.H"
#include "loads/ParticleLoad.H"
#include "materials/Material.H"
#include "schemes/ParticleTransfer.H"
#include "schemes/UpdateScheme.H"
#include "shapeFunctions/ShapeFunction.H"

#include <iostream>

namespace {
template <class Base> void list()
{
    std::cout << Base::kindName << ": " << gpic::Registry<Base>::validChoices() << '\n';
}
} // namespace

int main(int argc, char** argv)
{
    boost::program_options::options_description options("picToC options");
    return gpic::applicationMain(argc, argv, "picToC: list the run-time selectable types", options,
                                 [](const auto&) {
                                     list<gpic::Material>();
                                     list<gpic::BoundaryCondition>();
                                     list<gpic::ContactLaw>();
                                     list<gpic::ShapeFunction>();
                                     list<gpic::UpdateScheme>();
                                     list<gpic::ParticleTransfer>();
                                     list<gpic::FunctionObject>();
                                     list<gpic::Shape>();
                                     list<gpic::RigidBodyDriver>();
                                     list<gpic::ParticleLoad>();
                                 });
}
