#include "dictionary/DictionaryParser.H"

#include "core/error.H"
#include "dictionary/ValueBuilder.H"

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <unordered_map>

namespace gpic {

namespace fs = std::filesystem;

namespace {

const int maxIncludeDepth = 32;  // deeper is almost surely a file including itself
const int maxNestingDepth = 64;  // sub-dictionaries; the parser recurses, so this bounds its stack

//- Expand `$VAR` and `${VAR}` from the environment (in #include paths).
std::string expandEnvironment(const std::string& s, const Token& where)
{
    std::string out;
    std::size_t i = 0;
    while (i < s.size()) {
        if (s[i] != '$') {
            out += s[i++];
            continue;
        }
        std::string name;
        if (i + 1 < s.size() && s[i + 1] == '{') {
            const std::size_t close = s.find('}', i);
            if (close == std::string::npos)
                throw InputError(where.file, where.line, "unterminated '${' in '" + s + "'");
            name = s.substr(i + 2, close - i - 2);
            i = close + 1;
        } else {
            std::size_t j = i + 1;
            while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '_'))
                ++j;
            name = s.substr(i + 1, j - i - 1);
            i = j;
        }
        const char* value = name.empty() ? nullptr : std::getenv(name.c_str());
        if (!value)
            throw InputError(where.file, where.line,
                             "environment variable '" + name + "' in '" + s + "' is not set");
        out += value;
    }
    return out;
}

bool isUnsignedInteger(const std::string& s)
{
    if (s.empty() || s.size() > 9) return false;  // 9 digits cannot overflow a long
    for (char c : s)
        if (!std::isdigit(static_cast<unsigned char>(c))) return false;
    return true;
}

} // namespace

void DictionaryParser::parseFile(Dictionary& dict, const std::string& text,
                                 const std::string& displayName, const std::string& realPath)
{
    dict.name_ = displayName;
    dict.file_ = displayName;
    DictionaryParser parser;
    parser.realPaths_[displayName] = realPath;
    Stream in{tokenize(text, displayName)};
    parser.parseEntries(dict, in, nullptr);
    dict.realPaths_ = std::make_shared<const std::map<std::string, std::string>>(std::move(parser.realPaths_));
    relink(dict);
    dict.endLine_ = 1;
    for (char c : text) dict.endLine_ += c == '\n';
}

void DictionaryParser::setEntry(Dictionary& dict, const std::string& keyword,
                                const std::string& valueText)
{
    // Parse `keyword valueText;` as if read from the file; it has no line there.
    Stream in{tokenize(valueText, dict.file_)};
    for (Lexeme& l : in.lexemes) l.token.line = 0;
    in.lexemes.push_back({Token{Token::Kind::punctuation, ";", dict.file_, 0}, false});
    const Token key{Token::Kind::word, keyword, dict.file_, 0};
    DictionaryParser parser;
    parser.parseEntry(dict, key, in, Mode::replace);
    while (!in.atEnd() && isPunct(in.peek().token, ';')) in.next();
    if (!in.atEnd())
        throw InputError(dict.file_, 0,
                         "unexpected '" + in.peek().token.text + "' after the value of keyword '" +
                             keyword + "': '" + valueText + "'");
}

void DictionaryParser::parseEntries(Dictionary& dict, Stream& in, const Token* open)
{
    // Values written in this block, by keyword and line: a second one is legal (the later
    // wins, as in OpenFOAM) but more often a mistake than an intent, so it is said. A later
    // value over one from an #include or a $macro is the usual way to override and is not.
    // keyword -> the lines it was given at, hashed: a file of tens of thousands of bodies.
    std::unordered_map<std::string, std::vector<int>> written, writtenDicts;
    while (!in.atEnd()) {
        const Token& t = in.next();
        if (t.kind == Token::Kind::punctuation) {
            if (t.text == "}") {
                if (!open) throw InputError(t.file, t.line, "unexpected '}' with no matching '{'");
                dict.endLine_ = t.line;
                return;
            }
            if (t.text == ";") continue;  // a stray ';', as in `name { ... };`, is harmless
            throw InputError(t.file, t.line, "expected a keyword, found '" + t.text + "'");
        }
        if (t.kind == Token::Kind::string)
            throw InputError(t.file, t.line, "expected a keyword, found \"" + t.text + "\"");
        if (t.text[0] == '#')
            parseInclude(dict, t, in);
        else if (t.text[0] == '$')
            mergeMacro(dict, t, in);
        else {
            const bool isValue = in.atEnd() || !isPunct(in.peek().token, '{');
            if (isValue) {
                std::vector<int>& lines = written[t.text];
                for (const int line : lines)
                    warning(t.file, t.line,
                            "keyword '" + t.text + "' is given twice in dictionary " + dict.name_ +
                                " (first at line " + std::to_string(line) + "): the later value is used");
                lines.push_back(t.line);
            } else {
                std::vector<int>& lines = writtenDicts[t.text];
                for (const int line : lines) {
                    warning(t.file, t.line,
                            "sub-dictionary '" + t.text + "' is given twice in dictionary " + dict.name_ +
                                " (first at line " + std::to_string(line) +
                                "): the two are merged, the later entries win");
                    dict.repeated_.push_back({t.text, line, t.line});
                }
                lines.push_back(t.line);
            }
            parseEntry(dict, t, in, Mode::merge);
        }
    }
    if (open)
        throw InputError(open->file, open->line,
                         "unbalanced '{': dictionary " + dict.name_ +
                             " is not closed (missing '}')");
}

void DictionaryParser::parseEntry(Dictionary& dict, const Token& keyword, Stream& in, Mode mode)
{
    Entry entry;
    entry.keyword = keyword.text;
    entry.file = keyword.file;
    entry.line = keyword.line;
    if (!in.atEnd() && isPunct(in.peek().token, '{')) {
        const Token& open = in.next();
        if (nestingDepth_ >= maxNestingDepth)
            throw InputError(open.file, open.line,
                             "sub-dictionary '" + keyword.text + "' nested more than " +
                                 std::to_string(maxNestingDepth) + " deep in dictionary " + dict.name_ +
                                 ": is a '}' missing?");
        // Created in place so that its parent link already works for macros inside it.
        entry.dict = std::make_shared<Dictionary>();
        Dictionary& sub = *entry.dict;
        sub.name_ = dict.name_ + "/" + keyword.text;
        sub.file_ = keyword.file;
        sub.startLine_ = keyword.line;
        sub.parent_ = &dict;
        ++nestingDepth_;
        parseEntries(sub, in, &open);
        --nestingDepth_;
    } else {
        const Dictionary* copied = nullptr;
        entry.tokens = parseValue(dict, keyword, in, copied);
        if (copied) {
            entry.dict = std::make_shared<Dictionary>(*copied);
            entry.dict->file_ = keyword.file;
            entry.dict->startLine_ = entry.dict->endLine_ = keyword.line;
            setUsed(entry, false);  // the copy reports its own unused entries
        }
    }
    addEntry(dict, std::move(entry), mode);
}

std::vector<Token> DictionaryParser::parseValue(const Dictionary& dict, const Token& keyword,
                                                Stream& in, const Dictionary*& copied)
{
    ValueBuilder value;
    const Token* last = &keyword;  // a missing ';' belongs after this token...
    const Token* beforeLast = &keyword;  // ...or after this one, when `last` opens a dictionary
    const auto missingSemicolon = [&](const Token* after) {
        value.checkClosed();  // an open bracket explains the problem better
        return InputError(after->file, after->line,
                          "missing ';' after the value of keyword '" + keyword.text + "'");
    };
    for (;;) {
        if (in.atEnd()) throw missingSemicolon(last);
        const Token& t = in.peek().token;
        if (isPunct(t, ';')) {
            value.checkClosed();
            in.next();
            return value.tokens();
        }
        if (isPunct(t, '}')) throw missingSemicolon(last);
        if (isPunct(t, '{')) throw missingSemicolon(beforeLast);  // `a 1 <newline> b { ... }`
        in.next();
        if (t.kind == Token::Kind::word && t.text[0] == '$') {
            const Entry& source = lookupMacro(dict, t);
            if (!source.dict) {
                for (const Token& s : source.tokens) value.add(s);
            } else if (value.tokens().empty() && !in.atEnd() && isPunct(in.peek().token, ';')) {
                copied = source.dict.get();
            } else {
                throw InputError(t.file, t.line,
                                 "macro '" + t.text + "' names a dictionary, so it must be the "
                                 "whole value: " + keyword.text + " " + t.text + ";");
            }
        } else if (t.kind == Token::Kind::word && t.text[0] == '#') {
            throw InputError(t.file, t.line,
                             "directive '" + t.text + "' is only allowed between entries");
        } else if (t.kind == Token::Kind::word && isUnsignedInteger(t.text) && !in.atEnd() &&
                   isPunct(in.peek().token, '(') &&
                   (in.peek().glued || value.tokens().empty())) {
            // A length prefix: `3(1 2 3)`, or OpenFOAM's long-list layout `N (` as the whole
            // value. `(0 (1 2))` keeps its 0, an element written apart from the list after it.
            value.add(in.next(), std::atol(t.text.c_str()));
        } else {
            value.add(t);
        }
        beforeLast = last;
        last = &t;
    }
}

void DictionaryParser::parseInclude(Dictionary& dict, const Token& directive, Stream& in)
{
    const bool optional = directive.text == "#includeIfPresent";
    if (directive.text != "#include" && !optional)
        throw InputError(directive.file, directive.line,
                         "unknown directive '" + directive.text +
                             "' (supported: #include, #includeIfPresent)");
    if (in.atEnd() || in.peek().token.kind != Token::Kind::string)
        throw InputError(directive.file, directive.line,
                         directive.text + " needs a quoted file name: " + directive.text +
                             " \"file\"");
    const Token& name = in.next();
    if (name.text.empty())
        throw InputError(name.file, name.line, directive.text + " needs a file name");
    if (!in.atEnd() && isPunct(in.peek().token, ';')) in.next();  // tolerated, as in OpenFOAM
    if (includeDepth_ >= maxIncludeDepth)
        throw InputError(directive.file, directive.line,
                         "#include nested more than " + std::to_string(maxIncludeDepth) +
                             " deep: does a file include itself?");

    // Relative paths are relative to the including file, both on disk and in messages.
    const fs::path path = expandEnvironment(name.text, name);
    std::string realPath = path.string();
    std::string displayName = realPath;
    if (path.is_relative()) {
        const fs::path realDir = fs::path(realPaths_[directive.file]).parent_path();
        realPath = (realDir / path).lexically_normal().string();
        displayName = (fs::path(directive.file).parent_path() / path).lexically_normal().string();
    }
    std::string text;
    if (const std::string why = readText(realPath, text); !why.empty()) {
        if (optional && why == "cannot open file") return;
        throw InputError(directive.file, directive.line,
                         (why == "cannot open file" ? "cannot open #include file \"" + name.text + "\""
                                                    : "#include file \"" + name.text + "\": " + why) +
                             " (looked for " + realPath + ")");
    }
    realPaths_[displayName] = realPath;
    Stream included{tokenize(text, displayName)};
    ++includeDepth_;
    parseEntries(dict, included, nullptr);
    --includeDepth_;
}

std::string Dictionary::filePath(const std::string& keyword) const
{
    const std::string value = get<std::string>(keyword);
    const Entry* e = findEntry(keyword);
    const Token where = e->tokens.empty() ? Token{} : e->tokens.front();
    const fs::path path = expandEnvironment(value, where);
    if (path.empty()) fail(keyword, "'" + keyword + "' needs a file name");
    if (path.is_absolute()) return path.string();
    std::string holder = e->file;
    if (realPaths_)
        if (const auto found = realPaths_->find(e->file); found != realPaths_->end()) holder = found->second;
    return (fs::path(holder).parent_path() / path).lexically_normal().string();
}

} // namespace gpic
