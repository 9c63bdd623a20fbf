#include "dictionary/Dictionary.H"

#include "core/error.H"
#include "dictionary/DictionaryParser.H"
#include "dictionary/TokenConversion.H"
#include "dictionary/Tokenizer.H"

#include <algorithm>
#include <sstream>

namespace gpic {

namespace {
//- Kept apart from `keys()`: the header describes the file, not the case.
const char* const header = Dictionary::headerKeyword;

std::string joined(const std::vector<std::string>& words)
{
    std::string out;
    for (const std::string& w : words) out += (out.empty() ? "" : ", ") + w;
    return out;
}
} // namespace

// ---------------------------------------------------------------- reading

Dictionary Dictionary::readFile(const std::string& path, const std::string& displayName)
{
    std::string text;
    if (const std::string why = DictionaryParser::readText(path, text); !why.empty()) throw InputError(path, 0, why);
    Dictionary dict;
    DictionaryParser::parseFile(dict, text, displayName.empty() ? path : displayName, path);
    return dict;
}

Dictionary Dictionary::parse(const std::string& text, const std::string& fileName)
{
    Dictionary dict;
    DictionaryParser::parseFile(dict, text, fileName, fileName);
    return dict;
}

// ---------------------------------------------------------------- copy and move

Dictionary::Dictionary(const Dictionary& other)
    : name_(other.name_), file_(other.file_), startLine_(other.startLine_),
      endLine_(other.endLine_), parent_(other.parent_), repeated_(other.repeated_),
      realPaths_(other.realPaths_)
{
    // The copy's own parent stays the original's (it names the same place); everything below
    // it is a deep copy owned by, and linked to, the copy.
    entries_.reserve(other.entries_.size());
    for (const Entry& e : other.entries_) entries_.push_back(DictionaryParser::cloneEntry(e));
    index_ = other.index_;
    DictionaryParser::relink(*this);
}

Dictionary& Dictionary::operator=(const Dictionary& other)
{
    if (this != &other) *this = Dictionary(other);
    return *this;
}

Dictionary::Dictionary(Dictionary&& other) noexcept
    : name_(std::move(other.name_)), file_(std::move(other.file_)),
      startLine_(other.startLine_), endLine_(other.endLine_), parent_(other.parent_),
      entries_(std::move(other.entries_)), index_(std::move(other.index_)), repeated_(std::move(other.repeated_)),
      realPaths_(std::move(other.realPaths_))
{
    for (Entry& e : entries_)
        if (e.dict) e.dict->parent_ = this;  // names are unchanged: only the address moved
}

Dictionary& Dictionary::operator=(Dictionary&& other) noexcept
{
    if (this == &other) return *this;
    // Assigning to a sub-dictionary inside a tree (`top.addSubDict("x") = d`) keeps its place
    // there: its name and parent stay, and the new entries are renamed below it.
    const bool inTree =
        parent_ && std::any_of(parent_->entries_.begin(), parent_->entries_.end(),
                               [this](const Entry& e) { return e.dict.get() == this; });
    if (!inTree) {
        name_ = std::move(other.name_);
        parent_ = other.parent_;
    }
    file_ = std::move(other.file_);
    startLine_ = other.startLine_;
    endLine_ = other.endLine_;
    entries_ = std::move(other.entries_);
    index_ = std::move(other.index_);
    repeated_ = std::move(other.repeated_);
    realPaths_ = std::move(other.realPaths_);
    DictionaryParser::relink(*this);
    return *this;
}

Dictionary::~Dictionary() = default;

// ---------------------------------------------------------------- look-up

const Entry* Dictionary::findEntry(const std::string& keyword) const
{
    const Entry* e = DictionaryParser::entryIn(*this, keyword);
    if (e) e->used = true;
    return e;
}

bool Dictionary::found(const std::string& keyword) const { return findEntry(keyword) != nullptr; }

bool Dictionary::isDict(const std::string& keyword) const
{
    const Entry* e = findEntry(keyword);
    return e && e->dict;
}

std::vector<std::string> Dictionary::keys() const
{
    std::vector<std::string> out;
    for (const Entry& e : entries_)
        if (e.keyword != header) out.push_back(e.keyword);
    return out;
}

int Dictionary::lineOf(const std::string& keyword) const
{
    const Entry* e = DictionaryParser::entryIn(*this, keyword);
    return e ? e->line : startLine_;
}

void Dictionary::fail(const std::string& keyword, const std::string& message) const
{
    const Entry* e = DictionaryParser::entryIn(*this, keyword);
    throw InputError(e ? e->file : file_, e ? e->line : startLine_, message);
}

// ---------------------------------------------------------------- typed look-up

template <class T> T Dictionary::get(const std::string& keyword) const
{
    const Entry* e = findEntry(keyword);
    if (!e) DictionaryParser::failMissing(*this, keyword);
    T value{};
    const std::string problem =
        e->dict ? std::string("expected ") + expectedForm(&value) + ", found a sub-dictionary"
                : convertTokens(e->tokens, value);
    if (!problem.empty())
        throw InputError(e->file, e->line,
                         "keyword '" + keyword + "' in dictionary " + name_ + ": " + problem);
    return value;
}

template <class T> T Dictionary::getOrDefault(const std::string& keyword, const T& deflt) const
{
    return found(keyword) ? get<T>(keyword) : deflt;
}

template <class T>
T Dictionary::getChecked(const std::string& keyword, const std::function<bool(const T&)>& valid,
                         const std::string& requirement) const
{
    T value = get<T>(keyword);
    if (!valid(value)) {
        const Entry* e = findEntry(keyword);
        throw InputError(e->file, e->line,
                         "keyword '" + keyword + "' in dictionary " + name_ + ": value " +
                             writeTokens(e->tokens) + " is not valid; requires " + requirement);
    }
    return value;
}

#define GPIC_DICTIONARY_GET(T)                                                              \
    template T Dictionary::get<T>(const std::string&) const;                                \
    template T Dictionary::getOrDefault<T>(const std::string&, const T&) const;             \
    template T Dictionary::getChecked<T>(const std::string&,                                \
                                         const std::function<bool(const T&)>&,              \
                                         const std::string&) const;
GPIC_DICTIONARY_GET(double)
GPIC_DICTIONARY_GET(int)
GPIC_DICTIONARY_GET(long)
GPIC_DICTIONARY_GET(bool)
GPIC_DICTIONARY_GET(std::string)
GPIC_DICTIONARY_GET(Eigen::Vector2d)
GPIC_DICTIONARY_GET(Eigen::Vector3d)
GPIC_DICTIONARY_GET(std::vector<double>)
GPIC_DICTIONARY_GET(std::vector<int>)
GPIC_DICTIONARY_GET(std::vector<std::string>)
GPIC_DICTIONARY_GET(std::vector<Eigen::Vector2d>)
GPIC_DICTIONARY_GET(std::vector<Eigen::Vector3d>)
GPIC_DICTIONARY_GET(std::vector<std::vector<double>>)
#undef GPIC_DICTIONARY_GET

std::string Dictionary::getWord(const std::string& keyword,
                                const std::vector<std::string>& choices) const
{
    const Entry* e = findEntry(keyword);
    if (!e) DictionaryParser::failMissing(*this, keyword, "; valid choices: " + joined(choices));
    const std::string word = get<std::string>(keyword);
    if (std::find(choices.begin(), choices.end(), word) == choices.end())
        throw InputError(e->file, e->line,
                         "keyword '" + keyword + "' in dictionary " + name_ + ": '" + word +
                             "' is not a valid choice; valid choices: " + joined(choices));
    return word;
}

std::string Dictionary::getWordOrDefault(const std::string& keyword,
                                         const std::vector<std::string>& choices,
                                         const std::string& deflt) const
{
    return found(keyword) ? getWord(keyword, choices) : deflt;
}

const Dictionary& Dictionary::subDict(const std::string& keyword) const
{
    const Entry* e = findEntry(keyword);
    if (!e) DictionaryParser::failMissing(*this, keyword);
    if (!e->dict)
        throw InputError(e->file, e->line,
                         "keyword '" + keyword + "' in dictionary " + name_ +
                             ": expected a sub-dictionary { ... }, found '" +
                             writeTokens(e->tokens) + "'");
    return *e->dict;
}

const Dictionary* Dictionary::subDictPtr(const std::string& keyword) const
{
    const Entry* e = findEntry(keyword);
    return e && e->dict ? e->dict.get() : nullptr;
}

// ---------------------------------------------------------------- unused entries

void Dictionary::warnUnused() const
{
    for (const Entry& e : entries_) {
        if (e.keyword == header) continue;
        if (!e.used)
            warning(e.file, e.line,
                    "keyword '" + e.keyword + "' in dictionary " + name_ + " is not used");
        else if (e.dict)
            e.dict->warnUnused();  // an unused sub-dictionary is one warning, not one per entry
    }
}

std::vector<std::string> Dictionary::unusedKeys() const
{
    std::vector<std::string> out;
    for (const Entry& e : entries_) {
        if (e.keyword == header) continue;
        if (!e.used) {
            out.push_back(name_ + "/" + e.keyword);
        } else if (e.dict) {
            const std::vector<std::string> inner = e.dict->unusedKeys();
            out.insert(out.end(), inner.begin(), inner.end());
        }
    }
    return out;
}

// ---------------------------------------------------------------- building and writing

void Dictionary::set(const std::string& keyword, const std::string& valueText)
{
    DictionaryParser::setEntry(*this, keyword, valueText);
}

Dictionary& Dictionary::addSubDict(const std::string& keyword)
{
    const Entry* existing = DictionaryParser::entryIn(*this, keyword);
    if (!existing || !existing->dict) {
        Entry entry;
        entry.keyword = keyword;
        entry.file = file_;
        entry.dict = std::make_shared<Dictionary>();
        entry.dict->file_ = file_;
        DictionaryParser::addEntry(*this, std::move(entry), DictionaryParser::Mode::replace);
    }
    return *DictionaryParser::entryIn(*this, keyword)->dict;
}

std::string Dictionary::toString(int indent) const
{
    const std::string pad(static_cast<std::size_t>(std::max(indent, 0)), ' ');
    std::ostringstream out;
    for (const Entry& e : entries_) {
        if (e.dict) {
            out << pad << e.keyword << '\n'
                << pad << "{\n"
                << e.dict->toString(indent + 4) << pad << "}\n";
        } else {
            out << pad << e.keyword << (e.tokens.empty() ? "" : " ") << writeTokens(e.tokens)
                << ";\n";
        }
    }
    return out.str();
}

void Dictionary::refuseRepeats(const std::string& what) const
{
    if (repeated_.empty()) return;
    const Repeat& r = repeated_.front();
    throw InputError(file_, r.secondLine,
                     what + " '" + r.keyword + "' is given twice in " + name_ + " (first at line " +
                         std::to_string(r.firstLine) + "): give each " + what + " its own name");
}

std::string fileHeader(const std::string& object, const std::string& location)
{
    std::string line = std::string(Dictionary::headerKeyword) + " { version 2.0; format ascii; class dictionary; ";
    if (!location.empty()) line += "location \"" + location + "\"; ";
    return line + "object " + object + "; }\n";
}

} // namespace gpic
