// Dictionary: OpenFOAM syntax, #include, $macros, typed look-up, messages, unused keywords.
#include "core/error.H"
#include "dictionary/Dictionary.H"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>

using namespace gpic;
namespace fs = std::filesystem;

namespace {

//- what() of the InputError `f` throws; a marker when it throws none.
std::string errorOf(const std::function<void()>& f)
{
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "<no InputError>";
}

bool startsWith(const std::string& s, const std::string& prefix)
{
    return s.compare(0, prefix.size(), prefix) == 0;
}

#define EXPECT_ERROR_STARTS(statement, prefix)                                               \
    do {                                                                                     \
        const std::string what_ = errorOf([&]() { statement; });                             \
        EXPECT_TRUE(startsWith(what_, prefix)) << "error: " << what_ << "\nwanted: " << prefix; \
    } while (false)

//- Files for #include and readFile tests, in a fresh directory per test.
class DictionaryFiles : public ::testing::Test {
protected:
    void SetUp() override
    {
        const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
        dir_ = fs::temp_directory_path() /
               ("gpicDictionaryTest-" + std::to_string(::getpid()) + "-" + test);
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override
    {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }
    //- Write `text` to `relative` below the test directory; returns the full path.
    std::string write(const std::string& relative, const std::string& text)
    {
        const fs::path path = dir_ / relative;
        fs::create_directories(path.parent_path());
        std::ofstream(path) << text;
        return path.string();
    }
    fs::path dir_;
};

} // namespace

// ---------------------------------------------------------------- syntax

TEST(Dictionary, ParsesKeywordValueEntries)
{
    const Dictionary d = Dictionary::parse("rho 2650;\nE 1e7;\nname sand;\nn 3;\n", "f");
    EXPECT_DOUBLE_EQ(d.get<double>("rho"), 2650);
    EXPECT_DOUBLE_EQ(d.get<double>("E"), 1e7);
    EXPECT_EQ(d.get<std::string>("name"), "sand");
    EXPECT_EQ(d.get<int>("n"), 3);
    EXPECT_EQ(d.get<long>("n"), 3L);
    EXPECT_EQ(d.keys(), (std::vector<std::string>{"rho", "E", "name", "n"}));
    EXPECT_EQ(d.lineOf("E"), 2);
    EXPECT_EQ(d.lineOf("missing"), 0);
    EXPECT_EQ(d.name(), "f");
    EXPECT_EQ(d.fileName(), "f");
    EXPECT_EQ(d.parent(), nullptr);
}

TEST(Dictionary, ValueMayHoldSeveralTokens)
{
    const Dictionary d = Dictionary::parse("value uniform (1 2);\nflag;\n", "f");
    const Entry* e = d.findEntry("value");
    ASSERT_NE(e, nullptr);
    ASSERT_EQ(e->tokens.size(), 5u);
    EXPECT_EQ(e->tokens[0].text, "uniform");
    EXPECT_EQ(e->tokens[1].kind, Token::Kind::punctuation);
    EXPECT_EQ(e->line, 1);
    EXPECT_TRUE(d.findEntry("flag")->tokens.empty());
}

TEST(Dictionary, SubDictionariesKnowNameParentAndLines)
{
    const Dictionary d = Dictionary::parse(
        "solver\n{\n    type explicit;\n    inner { a 1; }\n}\n", "system/controlDict");
    ASSERT_TRUE(d.isDict("solver"));
    const Dictionary& s = d.subDict("solver");
    EXPECT_EQ(s.name(), "system/controlDict/solver");
    EXPECT_EQ(s.fileName(), "system/controlDict");
    EXPECT_EQ(s.parent(), &d);
    EXPECT_EQ(s.startLine(), 1);
    EXPECT_EQ(s.endLine(), 5);
    const Dictionary& inner = s.subDict("inner");
    EXPECT_EQ(inner.name(), "system/controlDict/solver/inner");
    EXPECT_EQ(inner.parent(), &s);
    EXPECT_EQ(inner.get<int>("a"), 1);
    EXPECT_FALSE(s.isDict("type"));
    EXPECT_EQ(d.subDictPtr("nothing"), nullptr);
    EXPECT_EQ(s.subDictPtr("type"), nullptr);
    EXPECT_EQ(s.subDictPtr("inner"), &inner);
}

TEST(Dictionary, ListsAndNestedLists)
{
    const Dictionary d = Dictionary::parse(R"(
        v     (1 2.5 -3e2);
        ints  (1 -2 3);
        words (a "b c" d);
        pts   ((0 1) (2 3 0));
        table ((0 1) (1 2.5) (2 4 5));
        empty ();
    )", "f");
    EXPECT_EQ(d.get<std::vector<double>>("v"), (std::vector<double>{1, 2.5, -300}));
    EXPECT_EQ(d.get<std::vector<int>>("ints"), (std::vector<int>{1, -2, 3}));
    EXPECT_EQ(d.get<std::vector<std::string>>("words"),
              (std::vector<std::string>{"a", "b c", "d"}));
    const auto pts = d.get<std::vector<Eigen::Vector2d>>("pts");
    ASSERT_EQ(pts.size(), 2u);
    EXPECT_EQ(pts[1], Eigen::Vector2d(2, 3));
    const auto table = d.get<std::vector<std::vector<double>>>("table");
    ASSERT_EQ(table.size(), 3u);
    EXPECT_EQ(table[1], (std::vector<double>{1, 2.5}));
    EXPECT_EQ(table[2].size(), 3u);
    EXPECT_TRUE(d.get<std::vector<double>>("empty").empty());
    EXPECT_ERROR_STARTS(d.get<std::vector<double>>("words"),
                        "f:4: keyword 'words' in dictionary f: expected a list of numbers");
}

TEST(Dictionary, LengthPrefixIsDropped)
{
    const Dictionary d = Dictionary::parse(
        "a 3(1 2 3);\nt 2((0 1) (1 2));\nlong\n3\n(\n4\n5\n6\n)\n;\nnone 0();\n"
        "keep (0 (1 2));\n", "f");
    EXPECT_EQ(d.get<std::vector<double>>("a"), (std::vector<double>{1, 2, 3}));
    EXPECT_EQ(d.findEntry("a")->tokens.front().text, "(");
    EXPECT_EQ(d.get<std::vector<std::vector<double>>>("t").size(), 2u);
    EXPECT_EQ(d.get<std::vector<int>>("long"), (std::vector<int>{4, 5, 6}));
    EXPECT_TRUE(d.get<std::vector<double>>("none").empty());
    // An element written apart from the list after it is not a prefix.
    EXPECT_EQ(d.findEntry("keep")->tokens.size(), 7u);
}

TEST(Dictionary, LengthPrefixMustMatchTheList)
{
    EXPECT_EQ(errorOf([] { Dictionary::parse("a 1;\nb 3(1 2);\n", "f"); }),
              "f:2: list length prefix 3 does not match the 2 elements of the list");
}

TEST(Dictionary, CommentsInOddPlaces)
{
    const Dictionary d = Dictionary::parse(R"(/* a comment
   over two lines */
rho /* inline */ 2650 // trailing
;
v ( 1 // one
    2 /* two */ 3 );
sub // after a keyword
{ // after a brace
  a/*glued*/1; }
url "http://host//path/*x*/"; // comment markers inside a string are text
last 5; // no newline at the end)", "f");
    EXPECT_DOUBLE_EQ(d.get<double>("rho"), 2650);
    EXPECT_EQ(d.lineOf("rho"), 3);
    EXPECT_EQ(d.get<std::vector<int>>("v"), (std::vector<int>{1, 2, 3}));
    EXPECT_EQ(d.subDict("sub").get<int>("a"), 1);
    EXPECT_EQ(d.get<std::string>("url"), "http://host//path/*x*/");
    EXPECT_EQ(d.get<int>("last"), 5);
    EXPECT_EQ(d.lineOf("last"), 11);
}

TEST(Dictionary, QuotedStrings)
{
    const Dictionary d =
        Dictionary::parse(R"(title "two words"; esc "say \"hi\" \\ ok"; word plain;)", "f");
    EXPECT_EQ(d.get<std::string>("title"), "two words");
    EXPECT_EQ(d.findEntry("title")->tokens[0].kind, Token::Kind::string);
    EXPECT_EQ(d.get<std::string>("esc"), R"(say "hi" \ ok)");
    EXPECT_EQ(d.findEntry("word")->tokens[0].kind, Token::Kind::word);
}

TEST(Dictionary, FoamFileHeaderIsKeptButHidden)
{
    const Dictionary d = Dictionary::parse(
        "FoamFile\n{\n    version 2.0;\n    format ascii;\n    object materials;\n}\na 1;\n",
        "f");
    EXPECT_EQ(d.keys(), std::vector<std::string>{"a"});
    EXPECT_EQ(d.unusedKeys(), std::vector<std::string>{"f/a"});
    ASSERT_TRUE(d.isDict("FoamFile"));
    EXPECT_EQ(d.subDict("FoamFile").get<std::string>("object"), "materials");
    EXPECT_EQ(d.subDict("FoamFile").name(), "f/FoamFile");
}

TEST(Dictionary, RepeatedKeywordOverridesTheEarlierOne)
{
    const Dictionary d = Dictionary::parse("a 1;\nb 2;\na 3;\ns { x 1; y 2; }\ns { y 3; }\n", "f");
    EXPECT_EQ(d.get<int>("a"), 3);
    EXPECT_EQ(d.lineOf("a"), 3);
    EXPECT_EQ(d.keys(), (std::vector<std::string>{"a", "b", "s"}));
    // A repeated sub-dictionary merges, as in OpenFOAM: later entries override one by one.
    EXPECT_EQ(d.subDict("s").get<int>("x"), 1);
    EXPECT_EQ(d.subDict("s").get<int>("y"), 3);
}

TEST(Dictionary, AValueGivenTwiceInOneBlockIsSaidButAnOverrideOfAMacroIsNot)
{
    ::testing::internal::CaptureStderr();
    const Dictionary d = Dictionary::parse("a 1;\nb 2;\ns { x 1; }\na 3;\ns { x 2; }\n", "f");
    std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_EQ(d.get<int>("a"), 3);
    EXPECT_EQ(err, "Warning: f:4: keyword 'a' is given twice in dictionary f (first at line 1): the later value is used\n"
                   "Warning: f:5: sub-dictionary 's' is given twice in dictionary f (first at line 3): the two are "
                   "merged, the later entries win\n");
    ASSERT_EQ(d.repeatedSubDicts().size(), 1u);
    EXPECT_EQ(d.repeatedSubDicts().front().firstLine, 3);
    EXPECT_EQ(d.repeatedSubDicts().front().secondLine, 5);
    // Inside a sub-dictionary too; a repeated sub-dictionary merges, with a warning (its
    // values are checked within each block; where a repeated name is a mistake, as two bodies
    // of one name, the reader refuses it: Dictionary::refuseRepeats).
    ::testing::internal::CaptureStderr();
    Dictionary::parse("s { x 1;\n x 2; }\n", "f");
    err = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("f:2: keyword 'x' is given twice in dictionary f/s (first at line 1)"), std::string::npos) << err;
    // Overriding what a macro brought in is what macros are for.
    ::testing::internal::CaptureStderr();
    const Dictionary m = Dictionary::parse("base { E 1; nu 0.3; }\nsand { $base; E 2; }\n", "f");
    err = ::testing::internal::GetCapturedStderr();
    EXPECT_EQ(m.subDict("sand").get<int>("E"), 2);
    EXPECT_EQ(err, "");
}

TEST(Dictionary, AMissingKeywordNamesAnUnusedNearMissAsTheLikelyTypo)
{
    const Dictionary d = Dictionary::parse("deltaT 1e-4;\nendTme 2;\nmethod { kind a; }\n", "system/controlDict");
    d.get<double>("deltaT");
    EXPECT_EQ(errorOf([&] { d.get<double>("endTime"); }),
              "system/controlDict:2: keyword 'endTime' is undefined in dictionary system/controlDict; 'endTme' here "
              "is not used: a misspelling of it?");
    EXPECT_EQ(errorOf([&] { d.getWord("Method", {"a", "b"}); }),
              "system/controlDict:3: keyword 'Method' is undefined in dictionary system/controlDict; 'method' here "
              "is not used: a misspelling of it?; valid choices: a, b");
    // A keyword already read, or one too far off, is no guess.
    EXPECT_EQ(errorOf([&] { d.get<double>("deltaX"); }),
              "system/controlDict: keyword 'deltaX' is undefined in dictionary system/controlDict");
    EXPECT_EQ(errorOf([&] { d.subDict("writeFormat"); }),
              "system/controlDict: keyword 'writeFormat' is undefined in dictionary system/controlDict");
}

TEST(Dictionary, StrayPunctuationBetweenEntries)
{
    const Dictionary d = Dictionary::parse("s { a 1; };\n;\nb 2;\n", "f");
    EXPECT_EQ(d.keys(), (std::vector<std::string>{"s", "b"}));
    EXPECT_EQ(errorOf([] { Dictionary::parse("a 1;\n(1 2);\n", "f"); }),
              "f:2: expected a keyword, found '('");
    EXPECT_ERROR_STARTS(Dictionary::parse("\"quoted\" 1;", "f"), "f:1: expected a keyword");
    EXPECT_ERROR_STARTS(Dictionary::parse("a 1;\n#calc \"1+1\";\n", "f"),
                        "f:2: unknown directive '#calc'");
}

// ---------------------------------------------------------------- syntax errors

TEST(Dictionary, MissingSemicolonIsReportedAtItsLine)
{
    EXPECT_EQ(errorOf([] { Dictionary::parse("s\n{\n    a 1\n}\n", "f"); }),
              "f:3: missing ';' after the value of keyword 'a'");
    EXPECT_EQ(errorOf([] { Dictionary::parse("a 1;\nb 2\n", "f"); }),
              "f:2: missing ';' after the value of keyword 'b'");
    EXPECT_ERROR_STARTS(Dictionary::parse("a 1\nb { c 1; }\n", "f"), "f:1: missing ';'");
}

TEST(Dictionary, MissingSemicolonBetweenValuesIsHintedOnUse)
{
    // `rho 2650 E 1e7;` is valid syntax; the typed look-up points at the likely cause.
    const Dictionary d = Dictionary::parse("rho 2650\nE 1e7;\n", "f");
    EXPECT_EQ(errorOf([&] { d.get<double>("rho"); }),
              "f:1: keyword 'rho' in dictionary f: expected a number, found '2650 E 1e7' "
              "(missing ';' at the end of line 1?)");
}

TEST(Dictionary, UnbalancedBraces)
{
    EXPECT_EQ(errorOf([] { Dictionary::parse("a 1;\ns\n{\n    b 1;\n", "f"); }),
              "f:3: unbalanced '{': dictionary f/s is not closed (missing '}')");
    EXPECT_EQ(errorOf([] { Dictionary::parse("a 1;\n}\n", "f"); }),
              "f:2: unexpected '}' with no matching '{'");
}

TEST(Dictionary, UnbalancedParentheses)
{
    EXPECT_EQ(errorOf([] { Dictionary::parse("a 1;\nv (1 2\n  3;\n", "f"); }),
              "f:2: unbalanced '(': missing ')'");
    EXPECT_EQ(errorOf([] { Dictionary::parse("v 1 2);", "f"); }),
              "f:1: unexpected ')' with no matching '('");
    EXPECT_EQ(errorOf([] { Dictionary::parse("a 1;\nv (1\n];", "f"); }),
              "f:3: unexpected ']': '(' opened at line 2 is not closed");
    EXPECT_ERROR_STARTS(Dictionary::parse("s { v (1 2 }", "f"), "f:1: unbalanced '('");
}

TEST(Dictionary, UnterminatedCommentAndString)
{
    EXPECT_EQ(errorOf([] { Dictionary::parse("a 1;\n/* open\n\nb 2;\n", "f"); }),
              "f:2: unterminated comment: '/*' without '*/'");
    EXPECT_EQ(errorOf([] { Dictionary::parse("a 1;\nb \"open;\nc 2;\n", "f"); }),
              "f:2: unterminated string: missing closing '\"'");
}

// ---------------------------------------------------------------- files and #include

TEST_F(DictionaryFiles, ReadFileMissingIsAnError)
{
    const std::string path = (dir_ / "nothere").string();
    try {
        Dictionary::readFile(path);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), path);
        EXPECT_EQ(e.line(), 0);
        EXPECT_EQ(e.message(), "cannot open file");
    }
    EXPECT_THROW(Dictionary::readFile(dir_.string()), InputError);  // a directory
}

TEST_F(DictionaryFiles, IncludeIsRelativeToTheIncludingFile)
{
    write("case/system/common", "nu 0.3;\n\nE 1e7;\n");
    const std::string path = write("case/constant/materials",
                                   "sand\n{\n    #include \"../system/common\"\n"
                                   "    rho 2650;\n}\n");
    const Dictionary d = Dictionary::readFile(path, "constant/materials");
    const Dictionary& sand = d.subDict("sand");
    EXPECT_DOUBLE_EQ(sand.get<double>("E"), 1e7);
    EXPECT_DOUBLE_EQ(sand.get<double>("rho"), 2650);
    EXPECT_EQ(sand.keys(), (std::vector<std::string>{"nu", "E", "rho"}));
    // Included entries carry the included file's name and line.
    EXPECT_EQ(sand.findEntry("E")->file, "system/common");
    EXPECT_EQ(sand.lineOf("E"), 3);
    EXPECT_EQ(sand.findEntry("rho")->file, "constant/materials");
    EXPECT_EQ(errorOf([&] {
                  sand.getChecked<double>("E", [](const double& e) { return e < 0; }, "E < 0");
              }),
              "system/common:3: keyword 'E' in dictionary constant/materials/sand: value 1e7 is "
              "not valid; requires E < 0");
}

TEST_F(DictionaryFiles, NestedIncludeResolvesAgainstEachFile)
{
    write("main", "#include \"sub/b\"\nlast 1;\n");
    write("sub/b", "b 2;\n#include \"c\"\n");
    write("sub/c", "\n\nc 3;\n");
    const Dictionary d = Dictionary::readFile((dir_ / "main").string(), "main");
    EXPECT_EQ(d.get<int>("b"), 2);
    EXPECT_EQ(d.get<int>("c"), 3);
    EXPECT_EQ(d.findEntry("c")->file, "sub/c");
    EXPECT_EQ(d.lineOf("c"), 3);
    EXPECT_EQ(d.keys(), (std::vector<std::string>{"b", "c", "last"}));
}

TEST_F(DictionaryFiles, IncludePathExpandsEnvironmentVariables)
{
    write("inc/one", "one 1;\n");
    write("inc/two", "two 2;\n");
    ::setenv("GPIC_DICTIONARY_TEST_DIR", dir_.c_str(), 1);
    const Dictionary d = Dictionary::parse(
        "#include \"$GPIC_DICTIONARY_TEST_DIR/inc/one\"\n"
        "#include \"${GPIC_DICTIONARY_TEST_DIR}/inc/two\"\n", "f");
    EXPECT_EQ(d.get<int>("one"), 1);
    EXPECT_EQ(d.get<int>("two"), 2);
    ::unsetenv("GPIC_DICTIONARY_TEST_UNSET");
    EXPECT_ERROR_STARTS(Dictionary::parse("a 1;\n#include \"$GPIC_DICTIONARY_TEST_UNSET/x\"", "f"),
                        "f:2: environment variable 'GPIC_DICTIONARY_TEST_UNSET'");
}

TEST_F(DictionaryFiles, MissingIncludeIsAnErrorAtTheDirective)
{
    const std::string path = write("main", "a 1;\n\n#include \"nothere\"\n");
    EXPECT_ERROR_STARTS(Dictionary::readFile(path, "system/main"),
                        "system/main:3: cannot open #include file \"nothere\"");
    EXPECT_ERROR_STARTS(Dictionary::parse("\n#include \"\"", "f"),
                        "f:2: #include needs a file name");
    const std::string optional = write("opt", "#includeIfPresent \"nothere\"\na 1;\n");
    EXPECT_EQ(Dictionary::readFile(optional).keys(), std::vector<std::string>{"a"});
}

TEST_F(DictionaryFiles, FilesThatAreNoDictionaryAreRefusedBeforeTheyAreRead)
{
    // A device would be read until memory runs out, a pipe would block.
    const std::string zero = write("zero", "#include \"/dev/zero\"\n");
    EXPECT_ERROR_STARTS(Dictionary::readFile(zero, "system/controlDict"),
                        "system/controlDict:1: #include file \"/dev/zero\": not a regular file");
    EXPECT_ERROR_STARTS(Dictionary::readFile("/dev/zero"), "/dev/zero: not a regular file");
    // #includeIfPresent skips a file that is not there, not one that is wrong.
    EXPECT_ERROR_STARTS(Dictionary::parse("#includeIfPresent \"/dev/zero\"\n", "f"),
                        "f:1: #include file \"/dev/zero\": not a regular file");
    // A file far larger than any case dictionary (sparse: no disk used).
    const fs::path big = dir_ / "big";
    std::ofstream(big).close();
    fs::resize_file(big, (64u << 20) + 1);
    EXPECT_ERROR_STARTS(Dictionary::readFile(big.string(), "constant/bodies"), big.string() + ": larger than 64 MiB");
}

TEST_F(DictionaryFiles, AByteOrderMarkIsNotPartOfTheText)
{
    const std::string path = write("bom", "\xEF\xBB\xBF// an editor's UTF-8 mark\na 1;\nb { c 2; }\n");
    const Dictionary d = Dictionary::readFile(path, "constant/g");
    EXPECT_EQ(d.keys(), (std::vector<std::string>{"a", "b"}));
    EXPECT_EQ(d.lineOf("a"), 2);
}

TEST(Dictionary, SubDictionariesNestedTooDeepAreAnErrorNotACrash)
{
    // 30 000 levels overflowed the parser's stack (exit 139); 64 are allowed.
    const auto nested = [](int depth) {
        std::string text;
        for (int k = 0; k < depth; ++k) text += "a {\n";
        text += "x 1;\n";
        for (int k = 0; k < depth; ++k) text += "}\n";
        return text;
    };
    EXPECT_NO_THROW(Dictionary::parse(nested(64), "f"));
    EXPECT_ERROR_STARTS(Dictionary::parse(nested(65), "f"), "f:65: sub-dictionary 'a' nested more than 64 deep");
    EXPECT_ERROR_STARTS(Dictionary::parse(nested(30000), "f"), "f:65: sub-dictionary 'a' nested more than 64 deep");
}

TEST_F(DictionaryFiles, ErrorsInsideAnIncludedFileNameThatFile)
{
    write("inc", "x 1;\ny 2\n");
    const std::string path = write("main", "#include \"inc\"\n");
    EXPECT_EQ(errorOf([&] { Dictionary::readFile(path, "main"); }),
              "inc:2: missing ';' after the value of keyword 'y'");
    const std::string self = write("self", "#include \"self\"\n");
    EXPECT_ERROR_STARTS(Dictionary::readFile(self, "self"), "self:1: #include nested more than");
}

// ---------------------------------------------------------------- macros

TEST(Dictionary, MacroReplacesValueTokens)
{
    const Dictionary d = Dictionary::parse(R"(rho 2650;
v (1 2);
clay { E 5; inner { k 7; } }
sand
{
    rho $rho;
    v $v;
    braces ${rho};
    deep { r $rho; }
}
x $clay.E;
y $clay/inner/k;
list ($rho $clay.E);
)", "f");
    const Dictionary& sand = d.subDict("sand");
    EXPECT_DOUBLE_EQ(sand.get<double>("rho"), 2650);
    EXPECT_EQ(sand.get<Eigen::Vector2d>("v"), Eigen::Vector2d(1, 2));
    EXPECT_DOUBLE_EQ(sand.get<double>("braces"), 2650);
    EXPECT_DOUBLE_EQ(sand.subDict("deep").get<double>("r"), 2650);
    EXPECT_EQ(d.get<int>("x"), 5);
    EXPECT_EQ(d.get<int>("y"), 7);
    EXPECT_EQ(d.get<std::vector<double>>("list"), (std::vector<double>{2650, 5}));
    // Entries read through a macro count as used.
    EXPECT_TRUE(d.unusedKeys().empty());
}

TEST(Dictionary, MacroCopiesOrMergesASubDictionary)
{
    const Dictionary d = Dictionary::parse(R"(defaults { rho 2650; nu 0.3; }
sand $defaults;
clay
{
    $defaults;
    nu 0.25;
    E 1e7;
}
)", "f");
    ASSERT_TRUE(d.isDict("sand"));
    const Dictionary& sand = d.subDict("sand");
    EXPECT_EQ(sand.name(), "f/sand");
    EXPECT_EQ(sand.parent(), &d);
    EXPECT_NE(&sand, &d.subDict("defaults"));
    EXPECT_DOUBLE_EQ(sand.get<double>("rho"), 2650);
    const Dictionary& clay = d.subDict("clay");
    EXPECT_EQ(clay.keys(), (std::vector<std::string>{"rho", "nu", "E"}));
    EXPECT_DOUBLE_EQ(clay.get<double>("nu"), 0.25);
    EXPECT_DOUBLE_EQ(clay.get<double>("rho"), 2650);
}

TEST(Dictionary, MacroCopiesAreCheckedForUnusedEntries)
{
    // The template is used up by the copies; each copy reports what its reader ignored.
    const Dictionary d = Dictionary::parse(
        "defaults { rho 1; rhoo 2; }\nsand $defaults;\nclay { $defaults; E 3; }\n", "f");
    d.subDict("sand").get<double>("rho");
    d.subDict("clay").get<double>("rho");
    d.subDict("clay").get<double>("E");
    EXPECT_EQ(d.unusedKeys(), (std::vector<std::string>{"f/sand/rhoo", "f/clay/rhoo"}));
    ::testing::internal::CaptureStderr();
    d.warnUnused();
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("f:1: keyword 'rhoo' in dictionary f/sand is not used"), std::string::npos)
        << err;
}

TEST(Dictionary, UndefinedOrMisusedMacroIsAnErrorAtItsLine)
{
    EXPECT_ERROR_STARTS(Dictionary::parse("a 1;\nb $c;\n", "f"), "f:2: macro '$c' is undefined");
    // Only earlier entries can be referred to.
    EXPECT_ERROR_STARTS(Dictionary::parse("b $c;\nc 1;\n", "f"), "f:1: macro '$c' is undefined");
    EXPECT_ERROR_STARTS(Dictionary::parse("s { a 1; }\n\nb 1 $s;\n", "f"),
                        "f:3: macro '$s' names a dictionary");
    EXPECT_ERROR_STARTS(Dictionary::parse("a 1;\ns { $a; }\n", "f"),
                        "f:2: macro '$a' names a value");
}

// ---------------------------------------------------------------- typed look-up and messages

TEST_F(DictionaryFiles, MissingKeywordMessageIsExact)
{
    const std::string path = write("case/constant/materials", "\nsand\n{\n    rho 2650;\n}\n");
    const Dictionary d = Dictionary::readFile(path, "constant/materials");
    try {
        d.subDict("sand").get<double>("E");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "constant/materials:2: keyword 'E' is undefined in dictionary "
                  "constant/materials/sand");
        EXPECT_EQ(e.message(), "keyword 'E' is undefined in dictionary constant/materials/sand");
        EXPECT_EQ(e.file(), "constant/materials");
        EXPECT_EQ(e.line(), 2);
    }
    EXPECT_EQ(errorOf([&] { d.get<double>("E"); }),
              "constant/materials: keyword 'E' is undefined in dictionary constant/materials");
    EXPECT_EQ(errorOf([&] { d.subDict("clay"); }),
              "constant/materials: keyword 'clay' is undefined in dictionary constant/materials");
}

TEST(Dictionary, WrongFormMessageIsExact)
{
    const Dictionary d =
        Dictionary::parse("sand\n{\n    E abc;\n    s { a 1; }\n}\n", "constant/materials");
    const Dictionary& sand = d.subDict("sand");
    EXPECT_EQ(errorOf([&] { sand.get<double>("E"); }),
              "constant/materials:3: keyword 'E' in dictionary constant/materials/sand: "
              "expected a number, found 'abc'");
    EXPECT_ERROR_STARTS(sand.get<double>("s"),
                        "constant/materials:4: keyword 's' in dictionary constant/materials/sand: "
                        "expected a number, found a sub-dictionary");
    EXPECT_ERROR_STARTS(sand.subDict("E"),
                        "constant/materials:3: keyword 'E' in dictionary constant/materials/sand: "
                        "expected a sub-dictionary");
}

TEST(Dictionary, NumbersAreStrict)
{
    const Dictionary d = Dictionary::parse(
        "a 1e7x;\nb 3.0;\nc 3;\nhuge 1e400;\nnotnum nan;\nbig 3000000000;\nneg -4;\n"
        "two 1 2;\nq \"1\";\nE inf;\nminusInf -inf;\n", "f");
    EXPECT_ERROR_STARTS(d.get<double>("a"), "f:1: keyword 'a' in dictionary f: expected a number");
    EXPECT_EQ(errorOf([&] { d.get<int>("b"); }),
              "f:2: keyword 'b' in dictionary f: expected an integer, found '3.0'");
    EXPECT_DOUBLE_EQ(d.get<double>("b"), 3.0);
    EXPECT_EQ(d.get<int>("c"), 3);
    EXPECT_DOUBLE_EQ(d.get<double>("c"), 3.0);
    EXPECT_THROW(d.get<double>("huge"), InputError);
    EXPECT_THROW(d.get<double>("notnum"), InputError);
    EXPECT_THROW(d.get<int>("big"), InputError);
    EXPECT_EQ(d.get<long>("big"), 3000000000L);
    EXPECT_EQ(d.get<int>("neg"), -4);
    EXPECT_THROW(d.get<double>("two"), InputError);
    EXPECT_THROW(d.get<double>("q"), InputError);
    EXPECT_EQ(errorOf([&] { d.get<double>("E"); }), "f:10: keyword 'E' in dictionary f: expected a number, found 'inf'");
    EXPECT_THROW(d.get<double>("minusInf"), InputError);
}

TEST(Dictionary, Switches)
{
    const Dictionary d =
        Dictionary::parse("a yes; b no; c on; d off; e true; f false; g maybe;", "f");
    EXPECT_TRUE(d.get<bool>("a"));
    EXPECT_FALSE(d.get<bool>("b"));
    EXPECT_TRUE(d.get<bool>("c"));
    EXPECT_FALSE(d.get<bool>("d"));
    EXPECT_TRUE(d.get<bool>("e"));
    EXPECT_FALSE(d.get<bool>("f"));
    EXPECT_EQ(errorOf([&] { d.get<bool>("g"); }),
              "f:1: keyword 'g' in dictionary f: expected a switch (yes/no/on/off/true/false), "
              "found 'maybe'");
}

TEST(Dictionary, VectorsArePlane)
{
    const Dictionary d = Dictionary::parse(
        "g (0 -9.81);\ng3 (0 -9.81 0);\nbad (1 2 3);\nshort (1);\npts ((0 0) (1 0 0.5));\n", "f");
    EXPECT_EQ(d.get<Eigen::Vector2d>("g"), Eigen::Vector2d(0, -9.81));
    EXPECT_EQ(d.get<Eigen::Vector2d>("g3"), Eigen::Vector2d(0, -9.81));
    EXPECT_ERROR_STARTS(d.get<Eigen::Vector2d>("bad"),
                        "f:3: keyword 'bad' in dictionary f: the third component must be 0");
    EXPECT_ERROR_STARTS(d.get<Eigen::Vector2d>("short"),
                        "f:4: keyword 'short' in dictionary f: expected a vector (x y)");
    EXPECT_ERROR_STARTS(d.get<std::vector<Eigen::Vector2d>>("pts"), "f:5: keyword 'pts' in dictionary f: "
                                                            "the third component must be 0");
}

TEST(Dictionary, VectorsOfThreeComponents)
{
    const Dictionary d = Dictionary::parse(
        "g (0 0 -9.81);\nplane (1 2);\nfour (1 2 3 4);\npts ((0 0 0) (1 0 0.5));\n", "f");
    EXPECT_EQ(d.get<Eigen::Vector3d>("g"), Eigen::Vector3d(0, 0, -9.81));
    EXPECT_ERROR_STARTS(d.get<Eigen::Vector3d>("plane"),
                        "f:2: keyword 'plane' in dictionary f: expected a vector (x y z)");
    EXPECT_ERROR_STARTS(d.get<Eigen::Vector3d>("four"),
                        "f:3: keyword 'four' in dictionary f: expected a vector (x y z)");
    const auto pts = d.get<std::vector<Eigen::Vector3d>>("pts");
    ASSERT_EQ(pts.size(), 2u);
    EXPECT_EQ(pts[1], Eigen::Vector3d(1, 0, 0.5));
}

TEST(Dictionary, UnitBracketsAreSkippedForNumbers)
{
    const Dictionary d = Dictionary::parse(
        "rho [kg/m^3] 2650;\nnu 1e-6 [0 2 -1 0 0 0 0];\ng [m/s^2] (0 -9.81);\nl ([m] 1 2);\n",
        "f");
    EXPECT_DOUBLE_EQ(d.get<double>("rho"), 2650);
    EXPECT_DOUBLE_EQ(d.get<double>("nu"), 1e-6);
    EXPECT_EQ(d.get<Eigen::Vector2d>("g"), Eigen::Vector2d(0, -9.81));
    EXPECT_EQ(d.get<std::vector<double>>("l"), (std::vector<double>{1, 2}));
    // The units stay in the entry, so they are written back.
    EXPECT_NE(d.toString().find("rho [kg/m^3] 2650;"), std::string::npos);
}

TEST(Dictionary, GetCheckedNamesTheRequirement)
{
    const Dictionary d = Dictionary::parse("E -5;\nnu 0.3;\n", "f");
    const auto positive = [](const double& x) { return x > 0; };
    EXPECT_EQ(errorOf([&] { d.getChecked<double>("E", positive, "E > 0"); }),
              "f:1: keyword 'E' in dictionary f: value -5 is not valid; requires E > 0");
    EXPECT_DOUBLE_EQ(d.getChecked<double>("nu", positive, "nu > 0"), 0.3);
    EXPECT_ERROR_STARTS(d.getChecked<double>("G", positive, "G > 0"),
                        "f: keyword 'G' is undefined in dictionary f");
}

TEST(Dictionary, GetWordListsTheChoices)
{
    const Dictionary d = Dictionary::parse("a 1;\ntype foo;\nscheme usl;\n", "f");
    EXPECT_EQ(errorOf([&] { d.getWord("type", {"a", "b", "c"}); }),
              "f:2: keyword 'type' in dictionary f: 'foo' is not a valid choice; "
              "valid choices: a, b, c");
    EXPECT_EQ(d.getWord("scheme", {"usf", "usl", "musl"}), "usl");
    EXPECT_EQ(d.getWordOrDefault("missing", {"x", "y"}, "y"), "y");
    EXPECT_EQ(d.getWordOrDefault("scheme", {"usf", "usl"}, "usf"), "usl");
    EXPECT_ERROR_STARTS(d.getWord("missing", {"x", "y"}), "f: keyword 'missing' is undefined");
    EXPECT_NE(errorOf([&] { d.getWord("missing", {"x", "y"}); }).find("valid choices: x, y"),
              std::string::npos);
}

TEST(Dictionary, GetOrDefault)
{
    const Dictionary d = Dictionary::parse("a 2;\nb abc;\n", "f");
    EXPECT_EQ(d.getOrDefault<int>("a", 7), 2);
    EXPECT_EQ(d.getOrDefault<int>("missing", 7), 7);
    EXPECT_EQ(d.getOrDefault<std::string>("missing", "x"), "x");
    EXPECT_EQ(d.getOrDefault<Eigen::Vector2d>("missing", Eigen::Vector2d(1, 2)), Eigen::Vector2d(1, 2));
    // Present but malformed is still an error: a typo must not silently become the default.
    EXPECT_THROW(d.getOrDefault<double>("b", 1.0), InputError);
}

TEST(Dictionary, FailPointsAtTheEntry)
{
    const Dictionary d = Dictionary::parse("s\n{\n    a 1;\n\n    b 2;\n}\n", "f");
    const Dictionary& s = d.subDict("s");
    EXPECT_EQ(errorOf([&] { s.fail("b", "b must be smaller than a"); }),
              "f:5: b must be smaller than a");
    EXPECT_EQ(errorOf([&] { s.fail("c", "c is required"); }), "f:1: c is required");
}

// ---------------------------------------------------------------- unused entries

TEST(Dictionary, UnusedEntriesAreReported)
{
    const Dictionary d = Dictionary::parse(
        "FoamFile { version 2.0; }\nused 1;\ntypo 2;\ns\n{\n    a 1;\n    b 2;\n}\nt { c 3; }\n",
        "f");
    d.get<int>("used");
    d.subDict("s").get<int>("a");
    EXPECT_EQ(d.unusedKeys(), (std::vector<std::string>{"f/typo", "f/s/b", "f/t"}));

    ::testing::internal::CaptureStderr();
    d.warnUnused();
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("Warning: f:3: keyword 'typo' in dictionary f is not used"),
              std::string::npos) << err;
    EXPECT_NE(err.find("Warning: f:7: keyword 'b' in dictionary f/s is not used"),
              std::string::npos) << err;
    EXPECT_EQ(err.find("FoamFile"), std::string::npos) << err;
    EXPECT_EQ(err.find("'c'"), std::string::npos) << "one warning per unused sub-dictionary";
}

TEST(Dictionary, EveryLookUpMarksUsed)
{
    const Dictionary d = Dictionary::parse("a 1; b 2; c { } d { } e 5; f 6; g 7;", "f");
    d.found("a");
    d.isDict("b");
    d.subDictPtr("c");
    d.findEntry("d");
    d.getOrDefault<int>("e", 0);
    d.lineOf("f");  // positions are not uses
    d.keys();
    EXPECT_EQ(d.unusedKeys(), (std::vector<std::string>{"f/f", "f/g"}));
}

// ---------------------------------------------------------------- building, writing, copying

TEST(Dictionary, SetAndAddSubDict)
{
    Dictionary d = Dictionary::parse("a 1;\n", "f");
    d.set("a", "2");
    d.set("v", "3(1 2 3)");
    d.set("title", "\"two words\"");
    d.set("b", "$a");
    EXPECT_EQ(d.get<int>("a"), 2);
    EXPECT_EQ(d.get<std::vector<int>>("v"), (std::vector<int>{1, 2, 3}));
    EXPECT_EQ(d.get<std::string>("title"), "two words");
    EXPECT_EQ(d.get<int>("b"), 2);
    EXPECT_EQ(d.keys(), (std::vector<std::string>{"a", "v", "title", "b"}));
    EXPECT_THROW(d.set("bad", "(1 2"), InputError);
    EXPECT_THROW(d.set("bad", "1; c 2"), InputError);

    Dictionary& sub = d.addSubDict("sub");
    EXPECT_EQ(sub.name(), "f/sub");
    EXPECT_EQ(sub.parent(), &d);
    sub.set("x", "3");
    EXPECT_EQ(&d.addSubDict("sub"), &sub);  // an existing one is returned as it is
    EXPECT_EQ(d.subDict("sub").get<int>("x"), 3);
    d.set("sub", "{ y 4; }");  // set replaces, it does not merge
    EXPECT_EQ(d.subDict("sub").keys(), std::vector<std::string>{"y"});
    EXPECT_EQ(d.subDict("sub").parent(), &d);
    d.addSubDict("a");  // replaces the value
    EXPECT_TRUE(d.isDict("a"));
}

TEST(Dictionary, ToStringParsesBackToTheSameContent)
{
    const Dictionary d = Dictionary::parse(R"(FoamFile { version 2.0; object x; }
rho 2650;
title "two words";
quote "say \"hi\"";
v 3(1 2 3);
table ((0 1) (1 2));
flag;
s
{
    type linear;
    inner { k (1 [m] 2); }
}
)", "f");
    const std::string text = d.toString();
    const Dictionary back = Dictionary::parse(text, "g");
    EXPECT_EQ(back.toString(), text);
    EXPECT_EQ(back.get<std::string>("title"), "two words");
    EXPECT_EQ(back.get<std::string>("quote"), "say \"hi\"");
    EXPECT_EQ(back.get<std::vector<double>>("v"), (std::vector<double>{1, 2, 3}));
    EXPECT_EQ(back.subDict("s").subDict("inner").get<std::vector<double>>("k"),
              (std::vector<double>{1, 2}));
    EXPECT_EQ(back.keys(), d.keys());
    EXPECT_NE(text.find("title \"two words\";"), std::string::npos) << text;
    EXPECT_NE(text.find("    inner\n    {\n        k (1 [m] 2);\n    }\n"), std::string::npos)
        << text;
}

TEST(Dictionary, CopiesKeepParentLinksAndNames)
{
    const Dictionary d = Dictionary::parse("s { a 1; t { b 2; } }\n", "f");
    Dictionary c = d;
    EXPECT_EQ(c.name(), "f");
    EXPECT_EQ(c.subDict("s").parent(), &c);
    EXPECT_EQ(c.subDict("s").subDict("t").parent(), &c.subDict("s"));
    EXPECT_EQ(c.subDict("s").subDict("t").name(), "f/s/t");
    EXPECT_NE(&c.subDict("s"), &d.subDict("s"));  // deep copy
    c.addSubDict("s").set("a", "5");
    EXPECT_EQ(d.subDict("s").get<int>("a"), 1);

    // A copied sub-dictionary keeps its name and its (original) parent.
    const Dictionary sc = d.subDict("s");
    EXPECT_EQ(sc.name(), "f/s");
    EXPECT_EQ(sc.parent(), &d);
    EXPECT_EQ(sc.subDict("t").parent(), &sc);

    Dictionary m = std::move(c);
    EXPECT_EQ(m.subDict("s").parent(), &m);
    EXPECT_EQ(m.subDict("s").get<int>("a"), 5);
    Dictionary a;
    a = d;
    EXPECT_EQ(a.subDict("s").parent(), &a);
    a = std::move(m);
    EXPECT_EQ(a.subDict("s").parent(), &a);

    // Assigning into a tree keeps the place in it.
    Dictionary top = Dictionary::parse("x { }\n", "top");
    Dictionary& x = top.addSubDict("x");
    x = d.subDict("s");
    EXPECT_EQ(x.name(), "top/x");
    EXPECT_EQ(x.parent(), &top);
    EXPECT_EQ(x.subDict("t").name(), "top/x/t");
    EXPECT_EQ(x.subDict("t").parent(), &x);

    std::vector<Dictionary> many(1, d);
    many.resize(20);  // reallocation moves the dictionaries
    EXPECT_EQ(many[0].subDict("s").parent(), &many[0]);
}
