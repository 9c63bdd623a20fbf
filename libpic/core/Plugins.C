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
} // namespace

const std::vector<std::string>& Plugins::opened() { return openedList(); }

void Plugins::open(const std::string& library, const std::string& file, int line)
{
    auto& list = openedList();
    if (std::find(list.begin(), list.end(), library) != list.end()) return;
    if (!dlopen(library.c_str(), RTLD_NOW | RTLD_GLOBAL)) {
        const char* why = dlerror();
        throw InputError(file, line,
                         "cannot load library '" + library + "': " + (why ? why : "unknown") +
                             " (is it on LD_LIBRARY_PATH? source etc/bashrc)");
    }
    list.push_back(library);
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
