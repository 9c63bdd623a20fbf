// picToC: lists every run-time selectable type by kind (like OpenFOAM's foamToC), after
// loading any libraries given with -libs. A type that a library other than the project's
// own registered is followed by that library's file name in brackets.
// `picToC -keywords TYPE` prints a type's keywords, units and defaults: the keyword table of
// its header, compiled in at build time (etc/python/keywordTables.py writes KeywordTables.H),
// as OpenFOAM's foamInfo prints a class's header documentation.
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

#include "KeywordTables.H"

#include <algorithm>
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

//- The keyword tables of `type` (one per kind that has a type of that name), columns aligned.
void printKeywords(const std::string& type)
{
    std::set<std::string> valid;
    bool found = false;
    for (const gpic::KeywordTable& table : gpic::keywordTables()) {
        valid.insert(table.type);
        if (table.type != type) continue;
        if (found) std::cout << '\n';
        found = true;
        std::cout << table.kind << ' ' << table.type << " (" << table.header << ")\n";
        if (table.rows.empty()) {
            std::cout << "  no keywords of its own\n";
            continue;
        }
        const std::vector<const char*>& titles = table.titles;
        std::vector<std::size_t> width(titles.size(), 0);
        for (std::size_t c = 0; c < titles.size(); ++c) width[c] = std::string(titles[c]).size();
        for (const auto& row : table.rows)
            for (std::size_t c = 0; c < row.size() && c < width.size(); ++c)
                width[c] = std::max(width[c], std::string(row[c]).size());
        const auto line = [&](const std::vector<const char*>& cells) {
            std::string text = " ";
            for (std::size_t c = 0; c < cells.size() && c < width.size(); ++c) {
                std::string cell(cells[c]);
                if (c + 1 < cells.size()) cell.resize(width[c], ' ');
                text += " " + cell;
            }
            std::cout << text << '\n';
        };
        line(titles);
        for (const auto& row : table.rows) line(row);
        for (const char* note : table.notes) std::cout << "  " << note << '\n';
    }
    if (found) return;
    std::string list;
    for (const std::string& name : valid) list += (list.empty() ? "" : ", ") + name;
    throw gpic::InputError("", 0, "picToC -keywords: no keyword table for type '" + type +
                                      "' (a library's own type documents its keywords in its header); valid types: " + list);
}
} // namespace

int main(int argc, char** argv)
{
    boost::program_options::options_description options("picToC options");
    options.add_options()("keywords", boost::program_options::value<std::string>(),
                          "print the keywords, units and defaults of the type named, e.g. -keywords mohrCoulomb");
    return gpic::applicationMain(argc, argv, "picToC: list the run-time selectable types ((2D): plane scenes only, (3D): 3D only)", options,
                                 [](const auto& vm) {
                                     if (vm.count("keywords")) {
                                         printKeywords(vm["keywords"].template as<std::string>());
                                         return;
                                     }
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
