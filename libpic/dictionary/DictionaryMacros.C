// `$name` macros of DictionaryParser: look-up through enclosing dictionaries and the merge of
// a whole dictionary with `$name;`.
#include "dictionary/DictionaryParser.H"

#include "core/error.H"

namespace gpic {

const Entry& DictionaryParser::lookupMacro(const Dictionary& dict, const Token& macro)
{
    std::string name = macro.text.substr(1);
    if (name.size() >= 2 && name.front() == '{' && name.back() == '}')
        name = name.substr(1, name.size() - 2);
    std::vector<std::string> path;  // `a.b` or `a/b`: entry b of sub-dictionary a
    std::size_t start = 0;
    for (std::size_t i = 0; i <= name.size(); ++i)
        if (i == name.size() || name[i] == '.' || name[i] == '/') {
            path.push_back(name.substr(start, i - start));
            start = i + 1;
        }

    for (const Dictionary* scope = &dict; scope; scope = scope->parent_) {
        // The whole name first: a keyword may itself contain a '.'.
        if (const Entry* e = entryIn(*scope, name)) {
            setUsed(*e, true);
            return *e;
        }
        std::vector<const Entry*> chain{entryIn(*scope, path[0])};
        for (std::size_t k = 1; k < path.size() && chain.back() && chain.back()->dict; ++k)
            chain.push_back(entryIn(*chain.back()->dict, path[k]));
        if (chain.size() == path.size() && chain.back()) {
            for (const Entry* e : chain) e->used = true;
            setUsed(*chain.back(), true);
            return *chain.back();
        }
    }
    throw InputError(macro.file, macro.line,
                     "macro '" + macro.text + "' is undefined: no earlier entry '" + name +
                         "' in dictionary " + dict.name_ + " or an enclosing one");
}

void DictionaryParser::mergeMacro(Dictionary& dict, const Token& macro, Stream& in)
{
    const Entry& source = lookupMacro(dict, macro);
    if (!source.dict)
        throw InputError(macro.file, macro.line,
                         "macro '" + macro.text + "' names a value; only a dictionary can be "
                         "merged by '" + macro.text + ";' between entries");
    if (!in.atEnd() && !isPunct(in.peek().token, '}')) {
        if (!isPunct(in.peek().token, ';'))
            throw InputError(macro.file, macro.line, "missing ';' after '" + macro.text + "'");
        in.next();
    }
    // Clone first: adding to `dict` may move the entries `source` lives among. The clones start
    // unused, so that what the model never reads is reported where it was merged in.
    std::vector<Entry> entries;
    for (const Entry& e : source.dict->entries_) {
        entries.push_back(cloneEntry(e));
        setUsed(entries.back(), false);
    }
    for (Entry& e : entries) addEntry(dict, std::move(e), Mode::merge);
}

} // namespace gpic
