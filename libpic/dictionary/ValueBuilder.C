#include "dictionary/ValueBuilder.H"

#include "core/error.H"
#include "dictionary/Tokenizer.H"

namespace gpic {

void ValueBuilder::countElement()
{
    // Only list elements count; words inside a unit bracket `[kg m^-3]` do not.
    if (!frames_.empty() && isPunct(frames_.back().open, '(')) ++frames_.back().count;
}

void ValueBuilder::add(const Token& token, long lengthPrefix)
{
    if (isPunct(token, '(') || isPunct(token, '[')) {
        if (isPunct(token, '(')) countElement();
        frames_.push_back({token, lengthPrefix, 0});
    } else if (isPunct(token, ')') || isPunct(token, ']')) {
        const char opener = isPunct(token, ')') ? '(' : '[';
        if (frames_.empty())
            throw InputError(token.file, token.line,
                             "unexpected '" + token.text + "' with no matching '" + opener + "'");
        const Frame frame = frames_.back();
        if (!isPunct(frame.open, opener))
            throw InputError(token.file, token.line,
                             "unexpected '" + token.text + "': '" + frame.open.text +
                                 "' opened at line " + std::to_string(frame.open.line) +
                                 " is not closed");
        frames_.pop_back();
        if (frame.expected >= 0 && frame.expected != frame.count)
            throw InputError(frame.open.file, frame.open.line,
                             "list length prefix " + std::to_string(frame.expected) +
                                 " does not match the " + std::to_string(frame.count) +
                                 " elements of the list");
    } else {
        countElement();
    }
    tokens_.push_back(token);
}

void ValueBuilder::checkClosed() const
{
    if (frames_.empty()) return;
    const Token& open = frames_.back().open;
    const char closer = isPunct(open, '(') ? ')' : ']';
    throw InputError(open.file, open.line,
                     "unbalanced '" + open.text + "': missing '" + closer + "'");
}

} // namespace gpic
