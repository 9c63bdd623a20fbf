// The case files as picInit and the solver's reader take them, damaged at random: each of a
// tutorial's dictionaries in turn gets one mutation (a token deleted, a line doubled or
// swapped, a number replaced by 0, -1, 1e308, nan, a word or a huge integer, a stray brace,
// parenthesis, semicolon or quote, a file cut short, an #include of itself, an undefined
// $macro, sub-dictionaries nested deep), and the case is initialised and read. Each attempt
// must end in a case that reads, or in one refusal of one line (InputError, or RunError for a
// limit); any other exception fails the test, and a crash or a hang fails it by itself.
// Deterministic (seeded), about 600 attempts; tests/scripts/fuzzDictionary.sh fuzzes the
// parser alone at length.
#include "case/CaseFiles.H"
#include "core/error.H"
#include "support/Applications.H"
#include "support/CaseRunner.H"

#include <gtest/gtest.h>

#include <fstream>
#include <cstdio>
#include <random>
#include <regex>
#include <string>
#include <vector>

using namespace gpic;
using namespace gpic::test;

namespace {

std::vector<std::string> lines(const std::string& text)
{
    std::vector<std::string> out;
    std::stringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

std::string joined(const std::vector<std::string>& ls)
{
    std::string out;
    for (const auto& l : ls) out += l + "\n";
    return out;
}

//- The text with one mutation chosen by rng; `self` is the file's name for an #include of itself.
std::string mutated(const std::string& text, std::mt19937& rng, const std::string& self)
{
    const auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
    std::vector<std::string> ls = lines(text);
    if (ls.empty()) return text;
    switch (pick(9)) {
    case 0: {  // a token deleted
        std::vector<std::pair<std::size_t, std::size_t>> tokens;
        for (std::size_t i = 0; i < text.size();) {
            if (std::isspace(static_cast<unsigned char>(text[i]))) { ++i; continue; }
            std::size_t j = i;
            while (j < text.size() && !std::isspace(static_cast<unsigned char>(text[j]))) ++j;
            tokens.emplace_back(i, j - i);
            i = j;
        }
        if (tokens.empty()) return text;
        const auto [at, length] = tokens[pick(tokens.size())];
        return text.substr(0, at) + text.substr(at + length);
    }
    case 1: {  // a line doubled
        const std::size_t k = pick(ls.size());
        ls.insert(ls.begin() + static_cast<long>(k), ls[k]);
        return joined(ls);
    }
    case 2: {  // two lines swapped
        std::swap(ls[pick(ls.size())], ls[pick(ls.size())]);
        return joined(ls);
    }
    case 3: {  // a number replaced
        static const std::regex number(R"([-+]?[0-9]+\.?[0-9]*(e[-+]?[0-9]+)?)");
        std::vector<std::pair<std::size_t, std::size_t>> found;
        for (auto it = std::sregex_iterator(text.begin(), text.end(), number); it != std::sregex_iterator(); ++it)
            found.emplace_back(static_cast<std::size_t>(it->position()), static_cast<std::size_t>(it->length()));
        if (found.empty()) return text;
        static const char* const values[] = {"0", "-1", "1e308", "nan", "inf", "abc", "1e-300", "2147483648", "-0"};
        const auto [at, length] = found[pick(found.size())];
        return text.substr(0, at) + values[pick(9)] + text.substr(at + length);
    }
    case 4: {  // a stray character
        static const char* const strays[] = {"{", "}", "(", ")", ";", "\"", "$", "/*"};
        const std::size_t at = pick(text.size() + 1);
        return text.substr(0, at) + strays[pick(8)] + text.substr(at);
    }
    case 5:  // cut short
        return text.substr(0, pick(text.size() + 1));
    case 6: {  // includes itself
        ls.insert(ls.begin() + static_cast<long>(pick(ls.size() + 1)), "#include \"" + self + "\"");
        return joined(ls);
    }
    case 7: {  // an undefined macro as a value
        ls.insert(ls.begin() + static_cast<long>(pick(ls.size() + 1)), "extra $undefinedMacro;");
        return joined(ls);
    }
    default: {  // sub-dictionaries nested deep
        const std::size_t depth = 40 + pick(60);
        std::string nest;
        for (std::size_t d = 0; d < depth; ++d) nest += "n" + std::to_string(d) + " { ";
        for (std::size_t d = 0; d < depth; ++d) nest += "} ";
        return text + nest + "\n";
    }
    }
}

//- Initialise and read the case in dir: it reads, or is refused in one line; anything else
//  is a failure naming the attempt.
template <int D> bool attempt(const fs::path& dir, const std::string& what)
{
    try {
        initialiseCase(dir.string(), true);
        RunOptions options;
        options.caseDir = dir.string();
        options.quiet = true;
        Simulation<D> simulation(options);
        return true;
    } catch (const InputError& e) {
        const std::string m = e.what();
        EXPECT_FALSE(m.empty()) << what;
        EXPECT_EQ(m.find('\n'), std::string::npos) << what << ": a refusal of more than one line: " << m;
    } catch (const RunError& e) {
        const std::string m = e.what();
        EXPECT_EQ(m.find('\n'), std::string::npos) << what << ": a refusal of more than one line: " << m;
    } catch (const std::exception& e) {
        ADD_FAILURE() << what << ": not a refusal of bad input: " << e.what();
    }
    return false;
}

template <int D> void fuzzTutorial(const std::string& tutorial, int perFile, unsigned seed)
{
    ScratchDir scratch{"caseFuzz"};
    const fs::path source = tutorialPath(tutorial);
    std::mt19937 rng(seed);
    int attempts = 0, read = 0;
    for (const char* folder : {"constant", "system"}) {
        for (const auto& entry : fs::directory_iterator(source / folder)) {
            if (!entry.is_regular_file()) continue;
            const std::string name = std::string(folder) + "/" + entry.path().filename().string();
            const std::string text = readText(entry.path());
            for (int k = 0; k < perFile; ++k) {
                const fs::path dir = scratch.path() / "case";
                fs::remove_all(dir);
                copyCase(source, dir);
                const std::string damaged = mutated(text, rng, entry.path().filename().string());
                std::ofstream(dir / name, std::ios::binary) << damaged;
                read += attempt<D>(dir, tutorial + " " + name + " mutation " + std::to_string(k) + ":\n" + damaged);
                ++attempts;
            }
        }
    }
    std::printf("%s: %d damaged cases, %d read, %d refused in one line\n", tutorial.c_str(), attempts, read,
                attempts - read);
    EXPECT_GT(attempts, 50);
    EXPECT_GT(read, attempts / 10) << "the undamaged case must read: most harmless mutations keep it readable";
    EXPECT_GT(attempts - read, attempts / 10);
}

} // namespace

TEST(CaseFuzz, thePlaneTutorialsDamagedAtRandomReadOrAreRefusedInOneLine)
{
    fuzzTutorial<2>("verification/twoDisks", 40, 1);
    fuzzTutorial<2>("contact/inclinedDisk", 30, 2);
}

#if GPIC_WITH_3D
TEST(CaseFuzz, aThreeDTutorialDamagedAtRandomReadsOrIsRefusedInOneLine)
{
    fuzzTutorial<3>("geotechnics/cylinderCollapse", 25, 3);
}
#endif
