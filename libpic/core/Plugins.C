#include "core/Plugins.H"
#include "core/Info.H"

#include "core/error.H"
#include "dictionary/Dictionary.H"

#include <dlfcn.h>

#include <algorithm>
#include <iostream>

namespace gpic {

namespace {
std::vector<std::string>& openedList()
{
    static std::vector<std::string> list;
    return list;
}
//- The conflicts met while a library is being opened (Plugins::open), as messages.
std::vector<std::string>& pendingConflicts()
{
    static std::vector<std::string> list;
    return list;
}

bool& opening()
{
    static bool flag = false;
    return flag;
}
} // namespace

const std::vector<std::string>& Plugins::opened() { return openedList(); }

std::string Plugins::libraryOf(const void* address)
{
    Dl_info where{};
    if (dladdr(address, &where) && where.dli_fname && *where.dli_fname) return where.dli_fname;
    return "the application";
}

void Plugins::registrationConflict(const std::string& kind, const std::string& name,
                                   const std::string& firstLibrary, const std::string& secondLibrary)
{
    const std::string message = kind + " type '" + name + "' of " + secondLibrary + " is already registered by " +
                                firstLibrary + ": give it another name";
    if (opening()) pendingConflicts().push_back(message);
    else std::cerr << "Warning: " << message << '\n';
}

void Plugins::open(const std::string& library, const std::string& file, int line)
{
    auto& list = openedList();
    // dlopen("") would hand back the program itself and load nothing, silently.
    if (library.empty())
        throw InputError(file, line, "libs: an empty library name; give its file, e.g. (\"libmyMaterial.so\")");
    if (std::find(list.begin(), list.end(), library) != list.end()) return;
    pendingConflicts().clear();
    // Named before its initialisation runs (and flushed): a library whose static constructors
    // crash is then the last line of the log.
    info() << "Loading library " << library << std::endl;
    opening() = true;
    void* handle = dlopen(library.c_str(), RTLD_NOW | RTLD_GLOBAL);
    opening() = false;
    if (!handle) {
        const char* why = dlerror();
        throw InputError(file, line,
                         "cannot load library '" + library + "': " + (why ? why : "unknown") +
                             " (is it on LD_LIBRARY_PATH? source etc/bashrc)");
    }
    list.push_back(library);  // loaded either way: its code stays, so it is not opened twice
    if (!pendingConflicts().empty())
        throw InputError(file, line, "library '" + library + "': " + pendingConflicts().front());
    info() << "Loaded library " << library << '\n';
}

void Plugins::open(const Dictionary& dict, const std::string& keyword)
{
    const Entry* entry = dict.findEntry(keyword);
    if (!entry) return;
    for (const auto& lib : dict.get<std::vector<std::string>>(keyword))
        open(lib, entry->file, entry->line);
}

} // namespace gpic
