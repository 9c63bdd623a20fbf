#include "dictionary/Tokenizer.H"

#include "core/error.H"

#include <cctype>
#include <cstring>

namespace gpic {

namespace {

const char* const punctuation = ";{}()[]";

bool isSpace(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

//- A word runs until space, punctuation, a quote or the start of a comment.
bool endsWord(const std::string& text, std::size_t i)
{
    const char c = text[i];
    if (isSpace(c) || c == '"' || std::strchr(punctuation, c)) return true;
    return c == '/' && i + 1 < text.size() && (text[i + 1] == '/' || text[i + 1] == '*');
}

std::string quote(const std::string& s)
{
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + '"';
}

} // namespace

bool isPunct(const Token& token, char c)
{
    return token.kind == Token::Kind::punctuation && token.text.size() == 1 && token.text[0] == c;
}

std::vector<Lexeme> tokenize(const std::string& text, const std::string& fileName)
{
    std::vector<Lexeme> out;
    int line = 1;
    bool glued = false;
    std::size_t i = 0;
    const std::size_t n = text.size();

    auto emit = [&](Token::Kind kind, std::string s, int at) {
        out.push_back({Token{kind, std::move(s), fileName, at}, glued && !out.empty()});
        glued = true;
    };

    while (i < n) {
        const char c = text[i];
        if (isSpace(c)) {
            if (c == '\n') ++line;
            ++i;
            glued = false;
        } else if (c == '/' && i + 1 < n && text[i + 1] == '/') {
            while (i < n && text[i] != '\n') ++i;  // the newline itself is counted above
            glued = false;
        } else if (c == '/' && i + 1 < n && text[i + 1] == '*') {
            const int start = line;
            const std::size_t close = text.find("*/", i + 2);
            if (close == std::string::npos)
                throw InputError(fileName, start, "unterminated comment: '/*' without '*/'");
            for (std::size_t k = i; k < close; ++k) line += text[k] == '\n';
            i = close + 2;
            glued = false;
        } else if (c == '"') {
            // A string may not span lines: a forgotten closing quote is then reported where
            // the string starts instead of at the end of the file.
            const int start = line;
            std::string s;
            for (++i; i < n && text[i] != '"' && text[i] != '\n'; ++i) {
                if (text[i] == '\\' && i + 1 < n && (text[i + 1] == '"' || text[i + 1] == '\\'))
                    ++i;
                s += text[i];
            }
            if (i >= n || text[i] != '"')
                throw InputError(fileName, start, "unterminated string: missing closing '\"'");
            ++i;
            emit(Token::Kind::string, std::move(s), start);
        } else if (std::strchr(punctuation, c)) {
            emit(Token::Kind::punctuation, std::string(1, c), line);
            ++i;
        } else {
            const std::size_t start = i;
            if (c == '$' && i + 1 < n && text[i + 1] == '{') {
                // `${name}` keeps its braces, which are punctuation elsewhere.
                const std::size_t close = text.find('}', i);
                if (close == std::string::npos || text.find('\n', i) < close)
                    throw InputError(fileName, line, "unterminated '${': missing '}'");
                i = close + 1;
            }
            while (i < n && !endsWord(text, i)) ++i;
            emit(Token::Kind::word, text.substr(start, i - start), line);
        }
    }
    return out;
}

std::string writeTokens(const std::vector<Token>& tokens)
{
    std::string out;
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        const Token& t = tokens[i];
        const Token* prev = i > 0 ? &tokens[i - 1] : nullptr;
        const bool afterOpen = prev && (isPunct(*prev, '(') || isPunct(*prev, '['));
        const bool closing = isPunct(t, ')') || isPunct(t, ']');
        if (i > 0 && !afterOpen && !closing) out += ' ';  // `(1 2)`, not `( 1 2 )`
        out += t.kind == Token::Kind::string ? quote(t.text) : t.text;
    }
    return out;
}

} // namespace gpic
