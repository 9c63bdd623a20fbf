// Tree edits of DictionaryParser that need Dictionary's private members: adding entries,
// deep copies, parent links and names, used flags.
#include "dictionary/DictionaryParser.H"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace gpic {

void DictionaryParser::addEntry(Dictionary& dict, Entry entry, Mode mode)
{
    if (entry.dict) {
        entry.dict->parent_ = &dict;
        entry.dict->name_ = dict.name_ + "/" + entry.keyword;
        relink(*entry.dict);
    }
    for (Entry& old : dict.entries_) {
        if (old.keyword != entry.keyword) continue;
        if (mode == Mode::merge && old.dict && entry.dict) {
            for (Entry& e : entry.dict->entries_) addEntry(*old.dict, std::move(e), mode);
        } else {
            old = std::move(entry);  // the later one wins
        }
        return;
    }
    dict.entries_.push_back(std::move(entry));
}

Entry DictionaryParser::cloneEntry(const Entry& entry)
{
    Entry copy = entry;
    if (entry.dict) copy.dict = std::make_shared<Dictionary>(*entry.dict);
    return copy;
}

void DictionaryParser::relink(Dictionary& dict)
{
    for (Entry& e : dict.entries_)
        if (e.dict) {
            e.dict->parent_ = &dict;
            e.dict->name_ = dict.name_ + "/" + e.keyword;
            relink(*e.dict);
        }
}

const Entry* DictionaryParser::entryIn(const Dictionary& dict, const std::string& keyword)
{
    for (const Entry& e : dict.entries_)
        if (e.keyword == keyword) return &e;
    return nullptr;
}

void DictionaryParser::setUsed(const Entry& entry, bool used)
{
    entry.used = used;
    if (entry.dict)
        for (const Entry& e : entry.dict->entries_) setUsed(e, used);
}

bool DictionaryParser::readText(const std::string& path, std::string& text)
{
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) return false;  // opens, but cannot be read
    std::ifstream file(path);
    if (!file) return false;
    std::ostringstream buffer;
    buffer << file.rdbuf();
    text = buffer.str();
    return true;
}

} // namespace gpic
