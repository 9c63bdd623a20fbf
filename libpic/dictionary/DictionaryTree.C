// Tree edits of DictionaryParser that need Dictionary's private members: adding entries,
// deep copies, parent links and names, used flags.
#include "dictionary/DictionaryParser.H"

#include "core/error.H"

#include <algorithm>
#include <cctype>
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
    if (const auto at = dict.index_.find(entry.keyword); at != dict.index_.end()) {
        Entry& old = dict.entries_[at->second];
        if (mode == Mode::merge && old.dict && entry.dict) {
            for (Entry& e : entry.dict->entries_) addEntry(*old.dict, std::move(e), mode);
        } else {
            old = std::move(entry);  // the later one wins
        }
        return;
    }
    dict.index_.emplace(entry.keyword, dict.entries_.size());
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
            e.dict->realPaths_ = dict.realPaths_;
            relink(*e.dict);
        }
}

const Entry* DictionaryParser::entryIn(const Dictionary& dict, const std::string& keyword)
{
    const auto at = dict.index_.find(keyword);
    return at == dict.index_.end() ? nullptr : &dict.entries_[at->second];
}

namespace {
//- Optimal string alignment distance: insertions, deletions, substitutions and swaps of two
//  neighbouring letters, the edits a typing slip makes.
std::size_t editDistance(const std::string& a, const std::string& b)
{
    std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
    for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i)
        for (std::size_t j = 1; j <= b.size(); ++j) {
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1])});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[a.size()][b.size()];
}

std::string lowered(std::string s)
{
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}
} // namespace

const Entry* DictionaryParser::likelyTypo(const Dictionary& dict, const std::string& keyword)
{
    // Short keywords are too close to each other for a guess to mean anything.
    const std::size_t allowed = keyword.size() < 4 ? 0 : keyword.size() < 8 ? 1 : 2;
    const Entry* best = nullptr;
    std::size_t bestDistance = allowed + 1;
    for (const Entry& e : dict.entries_) {
        if (e.used || e.keyword == Dictionary::headerKeyword) continue;  // the header describes the file
        const std::size_t distance = lowered(e.keyword) == lowered(keyword) ? 0 : editDistance(e.keyword, keyword);
        if (distance < bestDistance) {
            best = &e;
            bestDistance = distance;
        }
    }
    return best;
}

void DictionaryParser::failMissing(const Dictionary& dict, const std::string& keyword, const std::string& more)
{
    const std::string missing = "keyword '" + keyword + "' is undefined in dictionary " + dict.name_;
    if (const Entry* typo = likelyTypo(dict, keyword))
        throw InputError(typo->file, typo->line,
                         missing + "; '" + typo->keyword + "' here is not used: a misspelling of it?" + more);
    throw InputError(dict.file_, dict.startLine_, missing + more);
}

void DictionaryParser::setUsed(const Entry& entry, bool used)
{
    entry.used = used;
    if (entry.dict)
        for (const Entry& e : entry.dict->entries_) setUsed(e, used);
}

std::string DictionaryParser::readText(const std::string& path, std::string& text)
{
    namespace fs = std::filesystem;
    // The largest case dictionary we expect is a few MiB of points; more is a wrong file.
    constexpr std::uintmax_t maxBytes = 64u << 20;
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (ec || !fs::exists(status)) return "cannot open file";
    // A device or a pipe could be read without end (#include "/dev/zero"), a folder not at all.
    if (!fs::is_regular_file(status)) return "not a regular file";
    const std::uintmax_t size = fs::file_size(path, ec);
    if (!ec && size > maxBytes) return "larger than 64 MiB (" + std::to_string(size) + " bytes): not a case dictionary";
    std::ifstream file(path);
    if (!file) return "cannot open file";
    std::ostringstream buffer;
    buffer << file.rdbuf();
    text = buffer.str();
    // Some editors begin a UTF-8 file with a byte-order mark; it is not part of the text.
    if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);
    return {};
}

} // namespace gpic
