#include "core/Dictionary.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace poro {
namespace {

const std::string kFile = "case/system/controlDict";

// Line numbers in the comments are the 1-based lines the messages must report.
const std::string kControl = "# PoroSPH controlDict\n"  //  1
                             "application: poroSph\n"   //  2
                             "startTime: 0\n"           //  3
                             "endTime: 2.5\n"           //  4
                             "deltaT: 1e-4\n"           //  5
                             "writeControl: timeStep\n" //  6
                             "writeInterval: 100\n"     //  7
                             "adjustTimeStep: yes\n"    //  8
                             "gravity: [0, 0, -9.81]\n" //  9
                             "pressure:\n"              // 10
                             "  maxIterations: 50\n"    // 11
                             "  tolerance: 1e-8\n";     // 12

Dictionary parse(const std::string& text) { return Dictionary::parse(text, kFile); }

/// The message of the InputError `f` throws; a test failure if it throws nothing or something else.
template <class F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return "";
}

/// Message of getReal on the one-line dictionary "x: <value>" (so the line is 1).
std::string realError(const std::string& value, const Range& range = Range::any()) {
  const auto d = parse("x: " + value + "\n");
  return errorOf([&] { d.getReal("x", range); });
}

std::string intError(const std::string& value, const Range& range = Range::any()) {
  const auto d = parse("n: " + value + "\n");
  return errorOf([&] { d.getInt("n", range); });
}

// --- Range and editDistance ------------------------------------------------------------------------

TEST(Range, ContainsRespectsOpenAndClosedEnds) {
  EXPECT_FALSE(Range::positive().contains(0.0));
  EXPECT_TRUE(Range::positive().contains(1e-300));
  EXPECT_TRUE(Range::nonNegative().contains(0.0));
  EXPECT_FALSE(Range::nonNegative().contains(-1e-300));
  EXPECT_TRUE(Range::closed(0, 1).contains(1.0));
  EXPECT_FALSE(Range::open(0, 1).contains(1.0));
  EXPECT_FALSE(Range::open(0, 1).contains(0.0));
  EXPECT_TRUE(Range::halfOpen(0, 1).contains(0.0));
  EXPECT_FALSE(Range::halfOpen(0, 1).contains(1.0));
  EXPECT_TRUE(Range::atLeast(2).contains(2.0));
  EXPECT_TRUE(Range::any().contains(-1e300));
}

TEST(Range, RejectsNonFiniteEvenWithoutBounds) {
  EXPECT_FALSE(Range::any().contains(std::numeric_limits<double>::quiet_NaN()));
  EXPECT_FALSE(Range::any().contains(std::numeric_limits<double>::infinity()));
  EXPECT_FALSE(Range::nonNegative().contains(std::numeric_limits<double>::infinity()));
}

TEST(Range, Describe) {
  EXPECT_EQ(Range::positive().describe(), "> 0");
  EXPECT_EQ(Range::nonNegative().describe(), ">= 0");
  EXPECT_EQ(Range::atLeast(1).describe(), ">= 1");
  EXPECT_EQ(Range::halfOpen(0, 1).describe(), "in [0, 1)");
  EXPECT_EQ(Range::closed(0, 1).describe(), "in [0, 1]");
  EXPECT_EQ(Range::open(0, 0.5).describe(), "in (0, 0.5)");
  EXPECT_EQ((Range{0.0, 1.0, true, false}).describe(), "in (0, 1]");
  EXPECT_EQ((Range{std::nullopt, 0.1, false, true}).describe(), "< 0.1");
  EXPECT_EQ((Range{std::nullopt, 1e-6, false, false}).describe(), "<= 1e-06");
  EXPECT_EQ(Range::closed(1, 1e6).describe(), "in [1, 1000000]"); // a limit of iterations reads as one
  EXPECT_EQ(Range::any().describe(), "finite");
}

TEST(Dictionary, EditDistanceIsLevenshtein) {
  EXPECT_EQ(Dictionary::editDistance("", ""), 0u);
  EXPECT_EQ(Dictionary::editDistance("abc", ""), 3u);
  EXPECT_EQ(Dictionary::editDistance("", "abc"), 3u);
  EXPECT_EQ(Dictionary::editDistance("endTime", "endTime"), 0u);
  EXPECT_EQ(Dictionary::editDistance("endTim", "endTime"), 1u);  // insertion
  EXPECT_EQ(Dictionary::editDistance("endTime", "entTime"), 1u); // substitution
  EXPECT_EQ(Dictionary::editDistance("deltaT", "deltT"), 1u);    // deletion
  EXPECT_EQ(Dictionary::editDistance("kitten", "sitting"), 3u);
  EXPECT_EQ(Dictionary::editDistance("flaw", "lawn"), 2u);
  EXPECT_EQ(Dictionary::editDistance("sitting", "kitten"), 3u); // symmetric
}

// --- happy paths -----------------------------------------------------------------------------------

TEST(Dictionary, ReadsEveryScalarType) {
  const auto d = parse(kControl);
  EXPECT_EQ(d.getString("application"), "poroSph");
  EXPECT_DOUBLE_EQ(d.getReal("startTime", Range::nonNegative()), 0.0);
  EXPECT_DOUBLE_EQ(d.getReal("endTime", Range::positive()), 2.5);
  EXPECT_DOUBLE_EQ(d.getReal("deltaT", Range::positive()), 1e-4);
  EXPECT_EQ(d.getWord("writeControl", {"timeStep", "runTime"}), "timeStep");
  EXPECT_EQ(d.getInt("writeInterval", Range::atLeast(1)), 100);
  EXPECT_TRUE(d.getBool("adjustTimeStep"));
  EXPECT_EQ(d.getVec3("gravity"), Vec3(0, 0, -9.81));
  const auto p = d.subDict("pressure");
  EXPECT_EQ(p.getInt("maxIterations"), 50);
  EXPECT_DOUBLE_EQ(p.getReal("tolerance", Range::positive()), 1e-8);
  EXPECT_NO_THROW(d.checkUnknownKeys());
  EXPECT_NO_THROW(p.checkUnknownKeys());
}

TEST(Dictionary, NumberSpellings) {
  const auto d = parse("a: -3\nb: .5\nc: 2.\nd: +1E3\ne: '0.25'\nf: 1e6\ng: -0\n");
  EXPECT_DOUBLE_EQ(d.getReal("a"), -3.0);
  EXPECT_DOUBLE_EQ(d.getReal("b"), 0.5);
  EXPECT_DOUBLE_EQ(d.getReal("c"), 2.0);
  EXPECT_DOUBLE_EQ(d.getReal("d"), 1000.0);
  EXPECT_DOUBLE_EQ(d.getReal("e"), 0.25);
  EXPECT_EQ(d.getInt("f"), 1000000); // an exactly integral real is an integer
  EXPECT_EQ(d.getInt("a"), -3);
  EXPECT_EQ(d.getInt("g"), 0);
}

TEST(Dictionary, Bools) {
  const auto d = parse("a: true\nb: false\nc: yes\nd: no\ne: On\nf: OFF\n");
  EXPECT_TRUE(d.getBool("a"));
  EXPECT_FALSE(d.getBool("b"));
  EXPECT_TRUE(d.getBool("c"));
  EXPECT_FALSE(d.getBool("d"));
  EXPECT_TRUE(d.getBool("e"));
  EXPECT_FALSE(d.getBool("f"));
}

TEST(Dictionary, StringAcceptsAnyScalar) {
  const auto d = parse("name: 123\ntitle: \"a: b\"\n");
  EXPECT_EQ(d.getString("name"), "123");
  EXPECT_EQ(d.getString("title"), "a: b");
}

TEST(Dictionary, KeysFileLineWhere) {
  const auto d = parse(kControl);
  EXPECT_EQ(d.keys(),
            (std::vector<std::string>{"application", "startTime", "endTime", "deltaT", "writeControl",
                                      "writeInterval", "adjustTimeStep", "gravity", "pressure"}));
  EXPECT_EQ(d.file(), kFile);
  EXPECT_EQ(d.line(), 2);
  EXPECT_EQ(d.where("deltaT"), kFile + ":5");
  EXPECT_EQ(d.where("absent"), kFile + ":2");
  EXPECT_TRUE(d.has("deltaT"));
  EXPECT_FALSE(d.has("absent"));
  const auto p = d.subDict("pressure");
  EXPECT_EQ(p.line(), 10);
  EXPECT_EQ(p.where("tolerance"), kFile + ":12");
  EXPECT_EQ(p.keys(), (std::vector<std::string>{"maxIterations", "tolerance"}));
}

TEST(Dictionary, ReadsFile) {
  const std::string path = std::string(POROSPH_TEST_DATA) + "/dictionary/controlDict";
  const auto d = Dictionary::read(path);
  EXPECT_EQ(d.file(), path);
  EXPECT_DOUBLE_EQ(d.getReal("endTime"), 2.5);
  EXPECT_EQ(d.where("deltaT"), path + ":3");
  EXPECT_EQ(errorOf([&] { d.getReal("deltaT", Range::atLeast(1)); }),
            path + ":3: key 'deltaT': expected a number >= 1, got '1e-4'");
}

// --- defaults --------------------------------------------------------------------------------------

TEST(Dictionary, DefaultsWhenAbsentAndMarksKnown) {
  const auto d = parse("endTime: 1\n");
  EXPECT_DOUBLE_EQ(d.getReal("deltaT", 0.1, Range::positive()), 0.1);
  EXPECT_EQ(d.getInt("writeInterval", 7), 7);
  EXPECT_FALSE(d.getBool("adjustTimeStep", false));
  EXPECT_EQ(d.getString("title", "none"), "none");
  EXPECT_EQ(d.getWord("writeControl", {"timeStep", "runTime"}, "runTime"), "runTime");
  EXPECT_EQ(d.getVec3("gravity", Vec3(0, -9.81, 0)), Vec3(0, -9.81, 0));
  EXPECT_FALSE(d.optionalSubDict("pressure").has_value());
  // endTime is the only unread key; the hint list proves the defaulted keys were marked known.
  EXPECT_EQ(errorOf([&] { d.checkUnknownKeys(); }),
            kFile + ":1: unknown key 'endTime'; expected one of: adjustTimeStep, deltaT, gravity, pressure, "
                    "title, writeControl, writeInterval");
}

TEST(Dictionary, DefaultedGetterStillValidatesPresentValue) {
  const auto d = parse("endTime: 1\ndeltaT: -0.5\nmode: fast\n");
  EXPECT_DOUBLE_EQ(d.getReal("endTime", 9.0, Range::positive()), 1.0);
  EXPECT_EQ(errorOf([&] { d.getReal("deltaT", 0.1, Range::positive()); }),
            kFile + ":2: key 'deltaT': expected a number > 0, got '-0.5'");
  EXPECT_EQ(errorOf([&] {
              d.getWord("mode", {"slow", "exact"}, "slow");
            }),
            kFile + ":3: key 'mode': expected one of slow, exact, got 'fast'");
}

// --- missing keys ----------------------------------------------------------------------------------

TEST(Dictionary, MissingRequiredKeyReportsMappingLine) {
  const auto d = parse("\n# comment\nendTime: 1\nwriteControl: timeStep\n");
  EXPECT_EQ(errorOf([&] { d.getReal("deltaT"); }), kFile + ":3: missing required key 'deltaT'");
  EXPECT_EQ(errorOf([&] { d.getInt("n"); }), kFile + ":3: missing required key 'n'");
  EXPECT_EQ(errorOf([&] { d.getBool("b"); }), kFile + ":3: missing required key 'b'");
  EXPECT_EQ(errorOf([&] { d.getString("s"); }), kFile + ":3: missing required key 's'");
  EXPECT_EQ(errorOf([&] { d.getWord("w", {"a"}); }), kFile + ":3: missing required key 'w'");
  EXPECT_EQ(errorOf([&] { d.getVec3("g"); }), kFile + ":3: missing required key 'g'");
  EXPECT_EQ(errorOf([&] { d.subDict("pressure"); }), kFile + ":3: missing required key 'pressure'");
  EXPECT_EQ(errorOf([&] { d.getDictList("regions"); }), kFile + ":3: missing required key 'regions'");
}

TEST(Dictionary, MissingKeyInSubDictNamesFullPathAndSubDictLine) {
  const auto d = parse(kControl);
  const auto p = d.subDict("pressure");
  EXPECT_EQ(errorOf([&] { p.getReal("relaxation"); }),
            kFile + ":10: missing required key 'pressure.relaxation'");
}

// --- wrong type ------------------------------------------------------------------------------------

TEST(Dictionary, StringWhereNumberExpected) {
  EXPECT_EQ(realError("fast"), kFile + ":1: key 'x': expected a finite number, got 'fast'");
  EXPECT_EQ(realError("fast", Range::positive()), kFile + ":1: key 'x': expected a number > 0, got 'fast'");
  EXPECT_EQ(realError("0x10"), kFile + ":1: key 'x': expected a finite number, got '0x10'");
  EXPECT_EQ(realError("1.5.2"), kFile + ":1: key 'x': expected a finite number, got '1.5.2'");
  EXPECT_EQ(intError("many"), kFile + ":1: key 'n': expected an integer, got 'many'");
}

TEST(Dictionary, CollectionWhereScalarExpected) {
  const auto d = parse("a: 1\nsolver:\n  type: cg\nlist: [1, 2]\n");
  EXPECT_EQ(errorOf([&] { d.getReal("solver"); }),
            kFile + ":3: key 'solver': expected a finite number, got a mapping");
  EXPECT_EQ(errorOf([&] { d.getString("solver"); }),
            kFile + ":3: key 'solver': expected a string, got a mapping");
  EXPECT_EQ(errorOf([&] { d.getBool("list"); }),
            kFile + ":4: key 'list': expected true or false, got a sequence of 2 elements");
  EXPECT_EQ(errorOf([&] { d.getInt("list"); }),
            kFile + ":4: key 'list': expected an integer, got a sequence of 2 elements");
  EXPECT_EQ(errorOf([&] {
              d.getWord("solver", {"cg", "gmres"});
            }),
            kFile + ":3: key 'solver': expected one of cg, gmres, got a mapping");
  EXPECT_EQ(errorOf([&] { d.subDict("a"); }), kFile + ":1: key 'a': expected a mapping of keys, got '1'");
}

TEST(Dictionary, EmptyValueIsReportedOnItsKeyLine) {
  const auto d = parse("a: 1\nendTime:\n\n\nb: 2\n");
  EXPECT_EQ(errorOf([&] { d.getReal("endTime"); }),
            kFile + ":2: key 'endTime': expected a finite number, got an empty value");
  EXPECT_EQ(errorOf([&] { d.getString("endTime", "x"); }),
            kFile + ":2: key 'endTime': expected a string, got an empty value");
  // A mapping whose sub-keys are all commented out holds no value: it reads as empty, every sub-key at its default.
  EXPECT_TRUE(d.subDict("endTime").keys().empty());
}

TEST(Dictionary, BadBool) {
  const auto d = parse("a: 1\nflag: maybe\n");
  EXPECT_EQ(errorOf([&] { d.getBool("flag"); }),
            kFile + ":2: key 'flag': expected true or false, got 'maybe'");
}

TEST(Dictionary, WordListsChoicesAndHintsTypos) {
  const auto d = parse("writeControl: foo\nother: timestep\n");
  EXPECT_EQ(errorOf([&] {
              d.getWord("writeControl", {"timeStep", "runTime"});
            }),
            kFile + ":1: key 'writeControl': expected one of timeStep, runTime, got 'foo'");
  EXPECT_EQ(
      errorOf([&] {
        d.getWord("other", {"timeStep", "runTime"});
      }),
      kFile + ":2: key 'other': expected one of timeStep, runTime, got 'timestep'; did you mean 'timeStep'?");
}

TEST(Dictionary, Vec3NeedsExactlyThreeFiniteNumbers) {
  const auto d = parse("a: [1, 2]\nb: 5\nc: [1, x, 3]\nd:\n  - 1\n  - 2\n  - .nan\ne: {x: 1}\n");
  EXPECT_EQ(
      errorOf([&] { d.getVec3("a"); }),
      kFile + ":1: key 'a': expected a sequence [x, y, z] of 3 finite numbers, got a sequence of 2 elements");
  EXPECT_EQ(errorOf([&] { d.getVec3("b"); }),
            kFile + ":2: key 'b': expected a sequence [x, y, z] of 3 finite numbers, got '5'");
  EXPECT_EQ(errorOf([&] { d.getVec3("c"); }),
            kFile + ":3: key 'c': expected a finite number as component 2 of [x, y, z], got 'x'");
  // Block sequence: the bad component's own line.
  EXPECT_EQ(errorOf([&] { d.getVec3("d"); }),
            kFile + ":7: key 'd': expected a finite number as component 3 of [x, y, z], got '.nan'");
  EXPECT_EQ(errorOf([&] { d.getVec3("e"); }),
            kFile + ":8: key 'e': expected a sequence [x, y, z] of 3 finite numbers, got a mapping");
}

TEST(Dictionary, RealsNeedExactlyTheirCountInRange) {
  const auto d = parse("range: [0, 1]\nsize: [640]\nbad: [1, -2]\n");
  EXPECT_EQ(d.getReals("range", 2, {5, 6}), (std::vector<double>{0, 1}));
  EXPECT_EQ(d.getReals("absent", 2, {5, 6}), (std::vector<double>{5, 6}));
  EXPECT_EQ(errorOf([&] { d.getReals("size", 2, {}); }),
            kFile + ":2: key 'size': expected a sequence of 2 numbers, got a sequence of 1 element");
  EXPECT_EQ(errorOf([&] { d.getReals("bad", 2, {}, Range::positive()); }),
            kFile + ":3: key 'bad': expected a number > 0 as item 2 of a sequence of 2 numbers, got '-2'");
}

// --- ranges, NaN, inf, integers ------------------------------------------------------------------

TEST(Dictionary, OutOfRangeNamesFileLineKeyValueAndRange) {
  const auto d = parse("application: poroSph\nstartTime: 0\n\n# end of the run\n\n\nendTime: -1\n");
  EXPECT_EQ(errorOf([&] { d.getReal("endTime", Range::positive()); }),
            kFile + ":7: key 'endTime': expected a number > 0, got '-1'");
  EXPECT_EQ(errorOf([&] { d.getReal("endTime", Range::halfOpen(0, 1)); }),
            kFile + ":7: key 'endTime': expected a number in [0, 1), got '-1'");
  EXPECT_EQ(errorOf([&] { d.getInt("endTime", Range::atLeast(0)); }),
            kFile + ":7: key 'endTime': expected an integer >= 0, got '-1'");
}

TEST(Dictionary, SubDictErrorsUseFullKeyPath) {
  const auto d = parse(kControl);
  const auto p = d.subDict("pressure");
  EXPECT_EQ(errorOf([&] { p.getInt("maxIterations", Range::atLeast(100)); }),
            kFile + ":11: key 'pressure.maxIterations': expected an integer >= 100, got '50'");
}

TEST(Dictionary, RejectsNaNAndInfinity) {
  for (const char* v : {".nan", ".NaN", "nan", "NaN", ".inf", "-.inf", "+.Inf", "inf", "-infinity"})
    EXPECT_EQ(realError(v), kFile + ":1: key 'x': expected a finite number, got '" + v + "'") << v;
  EXPECT_EQ(realError("1e400"), kFile + ":1: key 'x': expected a finite number, got '1e400'");
  EXPECT_EQ(realError(".inf", Range::positive()),
            kFile + ":1: key 'x': expected a finite number > 0, got '.inf'");
  EXPECT_EQ(intError(".nan"), kFile + ":1: key 'n': expected an integer, got '.nan'");
}

TEST(Dictionary, IntRejectsFractionsAndOverflow) {
  EXPECT_EQ(intError("2.5"), kFile + ":1: key 'n': expected an integer, got '2.5'");
  EXPECT_EQ(intError("2.5", Range::positive()), kFile + ":1: key 'n': expected an integer > 0, got '2.5'");
  EXPECT_EQ(intError("99999999999999999999"),
            kFile + ":1: key 'n': expected an integer that fits in 64 bits, got '99999999999999999999'");
  EXPECT_EQ(intError("-99999999999999999999"),
            kFile + ":1: key 'n': expected an integer that fits in 64 bits, got '-99999999999999999999'");
  EXPECT_NE(intError("1e30").find("expected an integer"), std::string::npos);
  const auto d = parse("n: 9223372036854775807\nm: -9223372036854775808\n");
  EXPECT_EQ(d.getInt("n"), std::numeric_limits<long long>::max());
  EXPECT_EQ(d.getInt("m"), std::numeric_limits<long long>::min());
}

// --- unknown keys ----------------------------------------------------------------------------------

TEST(Dictionary, UnknownKeyWithHint) {
  const auto d = parse("startTime: 0\ndeltaT: 0.1\nendTim: 5\n");
  d.getReal("startTime");
  d.getReal("deltaT");
  d.getReal("endTime", 1.0);
  EXPECT_EQ(errorOf([&] { d.checkUnknownKeys(); }),
            kFile + ":3: unknown key 'endTim'; did you mean 'endTime'?");
}

TEST(Dictionary, UnknownKeyWithoutCloseMatchListsKnownKeys) {
  const auto d = parse("startTime: 0\nbanana: 1\n");
  d.getReal("startTime");
  d.getReal("endTime", 1.0);
  EXPECT_EQ(errorOf([&] { d.checkUnknownKeys(); }),
            kFile + ":2: unknown key 'banana'; expected one of: endTime, startTime");
  const auto empty = parse("banana: 1\n");
  EXPECT_EQ(errorOf([&] { empty.checkUnknownKeys(); }),
            kFile + ":1: unknown key 'banana'; no keys are expected here");
}

TEST(Dictionary, MarkKnownSilencesAKey) {
  const auto d = parse("libs: [a]\n");
  d.markKnown("libs");
  EXPECT_NO_THROW(d.checkUnknownKeys());
}

TEST(Dictionary, UnknownKeyInSubDict) {
  const auto d = parse("endTime: 1\npressure:\n  maxIterations: 5\n  tolerence: 1e-6\n");
  d.getReal("endTime");
  const auto p = d.subDict("pressure");
  p.getInt("maxIterations");
  p.getReal("tolerance", 1e-8);
  EXPECT_NO_THROW(d.checkUnknownKeys()); // "pressure" became known by subDict
  EXPECT_EQ(errorOf([&] { p.checkUnknownKeys(); }),
            kFile + ":4: unknown key 'pressure.tolerence'; did you mean 'tolerance'?");
}

TEST(Dictionary, SubDictKnownKeysDoNotLeakBetweenLevels) {
  // "tolerance" read at top level must not make pressure.tolerance known, nor the reverse.
  const auto d = parse("tolerance: 1\npressure:\n  tolerance: 2\n");
  d.getReal("tolerance");
  const auto p = d.subDict("pressure");
  EXPECT_NO_THROW(d.checkUnknownKeys());
  EXPECT_EQ(errorOf([&] { p.checkUnknownKeys(); }),
            kFile + ":3: unknown key 'pressure.tolerance'; did you mean 'tolerance', a key of the top level?");
}

TEST(Dictionary, UnknownKeyHintsIgnoreLetterCaseAndFindLeftOutLetters) {
  const auto d = parse("XSPH: 0.1\nmaxSkeletonDensityError: 0.2\n");
  d.getReal("xsph", 0.0);
  d.getReal("maxSkeletonParticleDensityError", 0.0);
  d.getReal("maxParticleDensityError", 0.0);
  EXPECT_EQ(errorOf([&] { d.checkUnknownKeys(); }), kFile + ":1: unknown key 'XSPH'; did you mean 'xsph'?");
  const auto e = parse("maxSkeletonDensityError: 0.2\n");
  e.getReal("maxSkeletonParticleDensityError", 0.0);
  e.getReal("maxParticleDensityError", 0.0);
  EXPECT_EQ(errorOf([&] { e.checkUnknownKeys(); }),
            kFile + ":1: unknown key 'maxSkeletonDensityError'; did you mean 'maxSkeletonParticleDensityError'?");
  const auto f = parse("poreFluidDensity: lattice\n");
  EXPECT_EQ(errorOf([&] { f.getWord("poreFluidDensity", {"paper", "latticeCorrected"}); }),
            kFile + ":1: key 'poreFluidDensity': expected one of paper, latticeCorrected, got 'lattice'; did you mean "
                    "'latticeCorrected'?");
}

TEST(Dictionary, AKeyAtTheWrongLevelIsPointedToItsOwn) {
  const auto d = parse("wallContact: allSkeletons\npressure:\n  maxIterations: 5\n");
  const auto p = d.subDict("pressure");
  p.getInt("maxIterations");
  p.getString("wallContact", "compressibleSkeletons");
  p.checkUnknownKeys();
  EXPECT_EQ(errorOf([&] { d.checkUnknownKeys(); }),
            kFile + ":1: unknown key 'wallContact'; did you mean 'pressure.wallContact', a key of 'pressure'?");
}

TEST(Dictionary, UnreadSubDictIsUnknownToParent) {
  const auto d = parse("endTime: 1\npresure:\n  tolerance: 2\n");
  d.getReal("endTime");
  d.optionalSubDict("pressure");
  EXPECT_EQ(errorOf([&] { d.checkUnknownKeys(); }),
            kFile + ":2: unknown key 'presure'; did you mean 'pressure'?");
}

TEST(Dictionary, OptionalSubDictPresent) {
  const auto d = parse("pressure:\n  tolerance: 2\n");
  const auto p = d.optionalSubDict("pressure");
  ASSERT_TRUE(p.has_value());
  EXPECT_DOUBLE_EQ(p->getReal("tolerance"), 2.0);
  EXPECT_NO_THROW(d.checkUnknownKeys());
  EXPECT_NO_THROW(p->checkUnknownKeys());
}

// --- dictionary lists ------------------------------------------------------------------------------

const std::string kParticles = "spacing: 0.01\n"     // 1
                               "regions:\n"          // 2
                               "  - name: sand\n"    // 3
                               "    porosity: 0.4\n" // 4
                               "  - name: water\n"   // 5
                               "    porosity: 1.2\n" // 6
                               "    colour: blue\n"; // 7

TEST(Dictionary, DictListElementsHaveIndexedPathsAndLines) {
  const auto d = parse(kParticles);
  const auto regions = d.getDictList("regions");
  ASSERT_EQ(regions.size(), 2u);
  EXPECT_EQ(regions[0].getString("name"), "sand");
  EXPECT_DOUBLE_EQ(regions[0].getReal("porosity", Range::halfOpen(0, 1)), 0.4);
  EXPECT_EQ(regions[1].line(), 5);
  EXPECT_EQ(regions[1].getString("name"), "water");
  EXPECT_EQ(errorOf([&] { regions[1].getReal("porosity", Range::halfOpen(0, 1)); }),
            kFile + ":6: key 'regions[1].porosity': expected a number in [0, 1), got '1.2'");
  EXPECT_EQ(errorOf([&] { regions[1].getReal("density"); }),
            kFile + ":5: missing required key 'regions[1].density'");
  EXPECT_NO_THROW(regions[0].checkUnknownKeys());
  EXPECT_EQ(errorOf([&] { regions[1].checkUnknownKeys(); }),
            kFile + ":7: unknown key 'regions[1].colour'; expected one of: density, name, porosity");
  d.getReal("spacing");
  EXPECT_NO_THROW(d.checkUnknownKeys()); // "regions" became known by getDictList
}

TEST(Dictionary, DictListErrors) {
  const auto d = parse("a: 1\nregions:\n  - name: sand\n  - 5\nempty: []\n");
  EXPECT_EQ(errorOf([&] { d.getDictList("a"); }),
            kFile + ":1: key 'a': expected a sequence of mappings, got '1'");
  EXPECT_EQ(errorOf([&] { d.getDictList("regions"); }),
            kFile + ":4: key 'regions[1]': expected a mapping of keys, got '5'");
  EXPECT_TRUE(d.getDictList("empty").empty());
}

// --- file-level errors -----------------------------------------------------------------------------

TEST(Dictionary, MalformedYamlReportsItsLine) {
  const std::string msg = errorOf([] { parse("endTime: 1\ndeltaT: 0.1\n  writeInterval: 3\n"); });
  EXPECT_EQ(msg.rfind(kFile + ":3: malformed YAML: ", 0), 0u) << msg;
  EXPECT_GT(msg.size(), (kFile + ":3: malformed YAML: ").size()) << "yaml-cpp's reason is missing";

  const std::string path = std::string(POROSPH_TEST_DATA) + "/dictionary/malformed";
  const std::string fromFile = errorOf([&] { Dictionary::read(path); });
  EXPECT_EQ(fromFile.rfind(path + ":3: malformed YAML: ", 0), 0u) << fromFile;

  const std::string flow = errorOf([] { parse("a: 1\nb: *undefined\n"); });
  EXPECT_EQ(flow.rfind(kFile + ":2: malformed YAML: ", 0), 0u) << flow;

  // yaml-cpp finds an unclosed bracket at the end of the input, one line past the last: name the last line.
  EXPECT_EQ(errorOf([] { parse("a: 1\nb: [1, 2\n"); }),
            kFile + ":2: malformed YAML (at the end of the file): end of sequence flow not found");
  EXPECT_EQ(errorOf([] { parse("a: 1\nb: [1, 2"); }),
            kFile + ":2: malformed YAML (at the end of the file): end of sequence flow not found");
}

TEST(Dictionary, MissingFile) {
  const std::string path = std::string(POROSPH_TEST_DATA) + "/dictionary/doesNotExist";
  EXPECT_EQ(errorOf([&] { Dictionary::read(path); }), path + ": cannot open file (No such file or directory)");
  const std::string inMissingDir = std::string(POROSPH_TEST_DATA) + "/noSuchDirectory/controlDict";
  EXPECT_EQ(errorOf([&] { Dictionary::read(inMissingDir); }),
            inMissingDir + ": cannot open file: there is no directory " + POROSPH_TEST_DATA + "/noSuchDirectory");
  const std::string dir = std::string(POROSPH_TEST_DATA) + "/dictionary";
  EXPECT_EQ(errorOf([&] { Dictionary::read(dir); }), dir + ": cannot open file (it is a directory)");
}

TEST(Dictionary, EmptyFile) {
  for (const char* name : {"empty", "commentsOnly"}) {
    const std::string path = std::string(POROSPH_TEST_DATA) + "/dictionary/" + name;
    EXPECT_EQ(errorOf([&] { Dictionary::read(path); }),
              path + ":1: expected a YAML mapping of keys, but the file is empty");
  }
  EXPECT_EQ(errorOf([] { parse(""); }), kFile + ":1: expected a YAML mapping of keys, but the file is empty");
}

TEST(Dictionary, AnOptionalDictionaryMissingEmptyOrOfCommentsOnlyHoldsNoKeys) {
  const std::string data = std::string(POROSPH_TEST_DATA) + "/dictionary/";
  for (const char* name : {"empty", "commentsOnly", "noSuchFile"})
    EXPECT_TRUE(Dictionary::readOptional(data + name).keys().empty()) << name;
  // Anything else is read as read() reads it.
  EXPECT_THROW(Dictionary::readOptional(data), InputError); // a directory
  EXPECT_EQ(Dictionary::parse("a: 1\n", kFile, true).getReal("a"), 1.0);
}

TEST(Dictionary, BinaryContentIsNamedWithLineAndColumn) {
  EXPECT_EQ(errorOf([] { parse(std::string("a: 1\nb: 2\0\n", 11)); }),
            kFile +
                ":2: byte 0x00 at column 5 is a control character; expected a YAML text file (is this a binary file?)");
  EXPECT_EQ(errorOf([] { parse("a: \xC3\x28\n"); }),
            kFile + ":1: byte 0xC3 at column 4 is not valid UTF-8; expected a YAML text file (is this a binary file?)");
  // Tabs, CR line ends and multi-byte UTF-8 (units, names) are text.
  EXPECT_EQ(parse("a: 1\t# \xC2\xB5m, \xE2\x84\xAB\r\nb: 2\r\n").getInt("b"), 2);
}

TEST(Dictionary, TopLevelMustBeAMapping) {
  EXPECT_EQ(errorOf([] { parse("# header\nhello\n"); }),
            kFile + ":2: expected a YAML mapping of keys, got 'hello'");
  EXPECT_EQ(errorOf([] { parse("- a\n- b\n"); }),
            kFile + ":1: expected a YAML mapping of keys, got a sequence of 2 elements");
  EXPECT_NO_THROW(parse("{}\n"));
}

TEST(Dictionary, RejectsSecondDocument) {
  EXPECT_EQ(errorOf([] { parse("a: 1\n---\nb: 2\n"); }),
            kFile + ":3: expected a single YAML document, found a second one");
  EXPECT_NO_THROW(parse("---\na: 1\n"));
}

TEST(Dictionary, RejectsDuplicateAndNonNameKeys) {
  EXPECT_EQ(errorOf([] { parse("endTime: 1\ndeltaT: 2\nendTime: 3\n"); }),
            kFile + ":3: duplicate key 'endTime' (first given at line 1)");
  const auto d = parse("pressure:\n  tol: 1\n  tol: 2\n");
  EXPECT_EQ(errorOf([&] { d.subDict("pressure"); }),
            kFile + ":3: duplicate key 'pressure.tol' (first given at line 2)");
  EXPECT_EQ(errorOf([] { parse("a: 1\n[x, y]: 2\n"); }),
            kFile + ":2: expected a key name, got a sequence of 2 elements as a key");
}

// --- fail, copy, move ------------------------------------------------------------------------------

TEST(Dictionary, FailUsesStandardPrefix) {
  const auto d = parse(kControl);
  EXPECT_EQ(errorOf([&] { d.fail("deltaT", "must be smaller than endTime"); }),
            kFile + ":5: key 'deltaT': must be smaller than endTime");
  const auto p = d.subDict("pressure");
  EXPECT_EQ(errorOf([&] { p.fail("tolerance", "too tight for maxIterations"); }),
            kFile + ":12: key 'pressure.tolerance': too tight for maxIterations");
  EXPECT_EQ(errorOf([&] { p.fail("absent", "needed when x is set"); }),
            kFile + ":10: key 'pressure.absent': needed when x is set");
}

TEST(Dictionary, CopiesShareKnownKeysAndStayIndependent) {
  const auto a = parse("x: 1\ny: 2\n");
  Dictionary b = a;
  b.getReal("x");
  b.getReal("y");
  EXPECT_NO_THROW(a.checkUnknownKeys()); // one known-key set per file

  // Assigning another dictionary to b must not change a (yaml-cpp nodes share data).
  b = parse("z: 3\n");
  EXPECT_EQ(a.keys(), (std::vector<std::string>{"x", "y"}));
  EXPECT_EQ(b.keys(), (std::vector<std::string>{"z"}));

  Dictionary c = std::move(b);
  EXPECT_DOUBLE_EQ(c.getReal("z"), 3.0);
  Dictionary d = parse("w: 4\n");
  d = std::move(c);
  EXPECT_DOUBLE_EQ(d.getReal("z"), 3.0);

  // A copied sub-dictionary outlives its parent.
  std::optional<Dictionary> sub;
  {
    const auto parent = parse("pressure:\n  tol: 5\n");
    sub = parent.subDict("pressure");
  }
  EXPECT_DOUBLE_EQ(sub->getReal("tol"), 5.0);
}

TEST(Dictionary, CanonicalIgnoresCommentsLayoutQuotingAndNumberSpelling) {
  const Dictionary a = Dictionary::parse("box: {min: [0, 0.2, 1e-3], max: [1, 1, 1], open: [yMax]}\n"
                                         "name: tank\nfixed: true\n",
                                         kFile);
  const Dictionary b = Dictionary::parse("# edited\nbox:\n  max: [1.0, 10e-1, 1]   # reordered keys\n"
                                         "  min: [-0, 0.20, 0.001]\n  open:\n    - yMax\n"
                                         "name: 'tank'\nfixed: \"true\"\n",
                                         kFile);
  for (const char* key : {"box", "name", "fixed"}) EXPECT_EQ(a.canonical(key), b.canonical(key)) << key;
  EXPECT_EQ(a.canonical("box"), "{max: [1, 1, 1], min: [0, 0.2, 0.001], open: [yMax]}");
  EXPECT_EQ(a.canonical("absent"), "");
  // Any other edit is a change.
  const Dictionary c = Dictionary::parse("box: {min: [0, 0.2, 2e-3], max: [1, 1, 1], open: [yMax, xMax]}\n", kFile);
  EXPECT_NE(a.canonical("box"), c.canonical("box"));
}

TEST(Dictionary, CanonicalReadsBackAsItself) {
  const Dictionary a = Dictionary::parse("v: [stone.stl, 'a b', \"quote\\\" and \\\\\", ~, null, 'null', '', "
                                         "'007', {k: [1, 2]}]\n",
                                         kFile);
  const std::string text = a.canonical("v");
  EXPECT_EQ(Dictionary::parse("v: " + text + "\n", kFile).canonical("v"), text);
  EXPECT_EQ(text, "[stone.stl, \"a b\", \"quote\\\" and \\\\\", ~, ~, \"null\", \"\", 7, {k: [1, 2]}]");
}

} // namespace
} // namespace poro
