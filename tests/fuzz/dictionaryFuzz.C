// libFuzzer target for the dictionary parser (tests/scripts/fuzzDictionary.sh builds and runs
// it): any text either parses, and then every entry reads back as a number, a word, a vector
// or a sub-dictionary or is refused, or is refused whole. A refusal is an InputError of one
// non-empty line; anything else (another exception, a crash, a hang, a sanitizer report) is
// a finding.
#include "core/error.H"
#include "dictionary/Dictionary.H"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace {

void expectOneLine(const gpic::InputError& e)
{
    const std::string what = e.what();
    if (what.empty() || what.find('\n') != std::string::npos) {
        std::cerr << "refusal is not one line: [" << what << "]\n";
        std::abort();
    }
}

//- Read every entry of d in each of the ways an application reads one.
void readAll(const gpic::Dictionary& d, int depth)
{
    if (depth > 64) return;
    for (const auto& key : d.keys()) {
        if (d.isDict(key)) {
            readAll(d.subDict(key), depth + 1);
            continue;
        }
        try { (void)d.get<double>(key); } catch (const gpic::InputError& e) { expectOneLine(e); }
        try { (void)d.get<std::string>(key); } catch (const gpic::InputError& e) { expectOneLine(e); }
        try { (void)d.get<Eigen::Vector2d>(key); } catch (const gpic::InputError& e) { expectOneLine(e); }
        try { (void)d.get<Eigen::Vector3d>(key); } catch (const gpic::InputError& e) { expectOneLine(e); }
        try { (void)d.get<std::vector<double>>(key); } catch (const gpic::InputError& e) { expectOneLine(e); }
        try { (void)d.get<long>(key); } catch (const gpic::InputError& e) { expectOneLine(e); }
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const gpic::Dictionary d = gpic::Dictionary::parse(text, "system/fuzzDict");
        readAll(d, 0);
    } catch (const gpic::InputError& e) {
        expectOneLine(e);
    }
    return 0;
}
