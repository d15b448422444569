// SPDX-License-Identifier: GPL-3.0-or-later
#include "case/Dictionary.hpp"
#include "TestSupport.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

namespace mpm {
namespace {

/// Run `f`, expect an InputError and return it for inspection.
using test::catchInputError;

/// Expect `f` to throw an InputError at `line` naming `key`, with `text` in its message.
void expectError(const std::function<void()>& f, int line, const std::string& key,
                 const std::string& text, const std::string& file = "test") {
    const InputError e = catchInputError(f);
    EXPECT_EQ(e.file(), file) << e.what();
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.key(), key) << e.what();
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos)
        << "message '" << e.what() << "' lacks '" << text << "'";
}

Dictionary parse(const std::string& text) {
    return Dictionary::fromString(text, "test");
}

/// Tests that read files: `file(text)` writes one into the test's temporary folder.
class DictionaryFile : public test::TempDirTest {
protected:
    std::filesystem::path file(const std::string& text) {
        const std::filesystem::path p = dir_ / ("dict" + std::to_string(files_++) + ".yaml");
        std::ofstream(p, std::ios::binary) << text;
        return p;
    }

private:
    int files_ = 0;
};

// Success paths

TEST(Dictionary, ReadsTypedEntries) {
    const Dictionary d = parse("rho: 2500\n"
                               "E: 1.5e7\n"
                               "nu: -0.25\n"
                               "steps: 100\n"
                               "big: 1e3\n"
                               "name: sand\n"
                               "scheme: USL\n"
                               "gravity: [0, -9.81, 0]\n"
                               "quoted: \"3.5\"\n"
                               "plus: +2\n");
    EXPECT_DOUBLE_EQ(d.getScalar("rho"), 2500.0);
    EXPECT_DOUBLE_EQ(d.getScalar("E", Bounds::positive()), 1.5e7);
    EXPECT_DOUBLE_EQ(d.getScalar("nu", Bounds::closed(-1.0, 0.5)), -0.25);
    EXPECT_EQ(d.getInt("steps", Bounds::positive()), 100);
    EXPECT_EQ(d.getInt("big"), 1000);
    EXPECT_EQ(d.getString("name"), "sand");
    EXPECT_EQ(d.getWord("scheme", {"USF", "USL", "MUSL"}), "USL");
    EXPECT_EQ(d.getVector("gravity", 3), (std::vector<double>{0.0, -9.81, 0.0}));
    EXPECT_EQ(d.getVector("gravity").size(), 3u);
    EXPECT_DOUBLE_EQ(d.getScalar("quoted"), 3.5);
    EXPECT_EQ(d.getInt("plus"), 2);
    EXPECT_NO_THROW(d.checkUnknownKeys());
}

TEST(Dictionary, StringOfNumberIsItsText) {
    const Dictionary d = parse("label: 007\n");
    EXPECT_EQ(d.getString("label"), "007");
}

TEST(Dictionary, OptionalEntriesFallBackToDefaults) {
    const Dictionary d = parse("present: 4\n");
    EXPECT_DOUBLE_EQ(d.getScalarOr("absent", 1.25), 1.25);
    EXPECT_DOUBLE_EQ(d.getScalarOr("present", 1.25), 4.0);
    EXPECT_EQ(d.getIntOr("absentInt", 7), 7);
    EXPECT_TRUE(d.getBoolOr("absentBool", true));
    EXPECT_EQ(d.getStringOr("absentString", "x"), "x");
    EXPECT_EQ(d.getVectorOr("absentVector", {1.0, 2.0}, 2), (std::vector<double>{1.0, 2.0}));
    EXPECT_EQ(d.getWordOr("absentWord", "USF", {"USF", "USL"}), "USF");
    EXPECT_NO_THROW(d.checkUnknownKeys());
}

TEST(Dictionary, OptionalEntryPresentIsStillChecked) {
    const Dictionary d = parse("dt: -1\nscheme: XYZ\n");
    expectError([&] { d.getScalarOr("dt", 1.0, Bounds::positive()); }, 1, "dt",
                "expected a number in (0, inf], got -1");
    expectError(
        [&] {
            d.getWordOr("scheme", "USF", {"USF", "USL"});
        },
        2, "scheme", "expected one of USF, USL; got 'XYZ'");
}

TEST(Dictionary, BoolForms) {
    const Dictionary d = parse("a: yes\nb: No\nc: TRUE\nd: false\ne: on\nf: Off\ng: maybe\n"
                               "h: 1\n");
    EXPECT_TRUE(d.getBool("a"));
    EXPECT_FALSE(d.getBool("b"));
    EXPECT_TRUE(d.getBool("c"));
    EXPECT_FALSE(d.getBool("d"));
    EXPECT_TRUE(d.getBool("e"));
    EXPECT_FALSE(d.getBool("f"));
    expectError([&] { d.getBool("g"); }, 7, "g", "expected yes/no/true/false/on/off");
    expectError([&] { d.getBool("h"); }, 8, "h", "expected yes/no/true/false/on/off");
}

TEST(Dictionary, HasAndIsDict) {
    const Dictionary d = parse("grid:\n  cellSize: 0.1\nvalue: 3\nempty:\n");
    EXPECT_TRUE(d.has("grid"));
    EXPECT_TRUE(d.has("empty"));
    EXPECT_FALSE(d.has("nothing"));
    EXPECT_TRUE(d.isDict("grid"));
    EXPECT_FALSE(d.isDict("value"));
    EXPECT_FALSE(d.isDict("nothing"));
    EXPECT_NO_THROW(d.checkUnknownKeys());
}

TEST(Dictionary, KeysInFileOrderWithoutMarkingRead) {
    const Dictionary d = parse("zeta: 1\nalpha: 2\nmid: 3\n");
    EXPECT_EQ(d.keys(), (std::vector<std::string>{"zeta", "alpha", "mid"}));
    expectError([&] { d.checkUnknownKeys(); }, 1, "zeta",
                "unknown key; this dictionary takes no entries");
}

TEST(Dictionary, EmptyInputIsAnEmptyMap) {
    const Dictionary d = parse("");
    EXPECT_TRUE(d.keys().empty());
    EXPECT_FALSE(d.has("x"));
    EXPECT_NO_THROW(d.checkUnknownKeys());
    const Dictionary c = parse("# only a comment\n");
    EXPECT_TRUE(c.keys().empty());
    expectError([&] { d.getScalar("x"); }, 0, "x", "missing required key");
}

TEST(Dictionary, SubDictAndPaths) {
    const Dictionary d = parse("materials:\n"
                               "  sand:\n"
                               "    rho: 1800\n"
                               "    phi: abc\n");
    const Dictionary materials = d.subDict("materials");
    EXPECT_EQ(materials.path(), "materials");
    const Dictionary sand = materials.subDict("sand");
    EXPECT_EQ(sand.path(), "materials.sand");
    EXPECT_EQ(sand.fileName(), "test");
    EXPECT_DOUBLE_EQ(sand.getScalar("rho"), 1800.0);
    expectError([&] { sand.getScalar("phi"); }, 4, "materials.sand.phi",
                "expected a number, got 'abc'");
    expectError([&] { sand.getScalar("E"); }, 3, "materials.sand.E", "missing required key");
    EXPECT_NO_THROW(d.checkUnknownKeys());
    EXPECT_NO_THROW(materials.checkUnknownKeys());
}

TEST(Dictionary, SubDictOfNonMapIsAnError) {
    const Dictionary d = parse("grid: 3\nlist: [1, 2]\n");
    expectError([&] { d.subDict("grid"); }, 1, "grid", "expected a map");
    expectError([&] { d.subDict("list"); }, 2, "list", "expected a map");
    expectError([&] { d.subDict("absent"); }, 1, "absent", "missing required key");
}

TEST(Dictionary, DictList) {
    const Dictionary d = parse("regions:\n"
                               "  - type: box\n"
                               "    min: [0, 0, 0]\n"
                               "  - type: sphere\n"
                               "    radius: -1\n"
                               "    tpye: cube\n"
                               "bad:\n"
                               "  - {a: 1}\n"
                               "  - 5\n");
    const std::vector<Dictionary> regions = d.dictList("regions");
    ASSERT_EQ(regions.size(), 2u);
    EXPECT_EQ(regions[0].path(), "regions[0]");
    EXPECT_EQ(regions[1].path(), "regions[1]");
    EXPECT_EQ(regions[0].getString("type"), "box");
    EXPECT_EQ(regions[0].getVector("min", 3).size(), 3u);
    EXPECT_NO_THROW(regions[0].checkUnknownKeys());
    EXPECT_EQ(regions[1].getString("type"), "sphere");
    expectError([&] { regions[1].getScalar("radius", Bounds::positive()); }, 5, "regions[1].radius",
                "expected a number in (0, inf], got -1");
    // Each entry has its own record of read keys.
    expectError([&] { regions[1].checkUnknownKeys(); }, 6, "regions[1].tpye",
                "did you mean 'type'?");
    expectError([&] { d.dictList("bad"); }, 9, "bad[1]", "expected a map");
}

TEST(Dictionary, VectorList) {
    const Dictionary d = parse("vertices:\n"
                               "  - [0, 0]\n"
                               "  - [1, 0]\n"
                               "  - [1, 1]\n"
                               "short:\n"
                               "  - [0, 0]\n"
                               "  - [1]\n"
                               "word:\n"
                               "  - [0, x]\n");
    const auto v = d.vectorList("vertices", 2);
    ASSERT_EQ(v.size(), 3u);
    EXPECT_EQ(v[2], (std::vector<double>{1.0, 1.0}));
    EXPECT_EQ(d.vectorList("short").size(), 2u);
    expectError([&] { d.vectorList("short", 2); }, 7, "short[1]",
                "expected a sequence of 2 numbers");
    expectError([&] { d.vectorList("word"); }, 9, "word[0]", "expected a number at index 1");
}

TEST(Dictionary, StringList) {
    const Dictionary d = parse("fields: [pressure, velocity]\n"
                               "empty: []\n"
                               "word: pressure\n"
                               "nested:\n"
                               "  - pressure\n"
                               "  - [a, b]\n");
    EXPECT_EQ(d.getStringList("fields"), (std::vector<std::string>{"pressure", "velocity"}));
    EXPECT_TRUE(d.getStringList("empty").empty());
    expectError([&] { d.getStringList("word"); }, 3, "word",
                "expected a sequence of strings, got 'pressure'");
    expectError([&] { d.getStringList("nested"); }, 6, "nested[1]",
                "expected a string, got a sequence");
    expectError([&] { d.getStringList("missing"); }, 1, "missing", "missing required key");
}

// Error kinds

TEST(Dictionary, MissingRequiredKey) {
    const Dictionary d = parse("a: 1\nb: 2\n");
    expectError([&] { d.getScalar("rho"); }, 1, "rho", "missing required key");
    expectError([&] { d.getString("name"); }, 1, "name", "missing required key");
    expectError([&] { d.getVector("g", 3); }, 1, "g", "missing required key");
    expectError([&] { d.dictList("regions"); }, 1, "regions", "missing required key");
}

TEST(Dictionary, MissingRequiredKeyNamesTheMisspeltOne) {
    // The typo's own line and name, not the map's first line.
    const Dictionary m = parse("sand:\n  type: druckerPrager\n  density: 1500\n"
                               "  frictionAngel: 30\n");
    const Dictionary sand = m.subDict("sand");
    sand.getString("type");
    sand.getScalar("density");
    expectError([&] { sand.getScalar("frictionAngle"); }, 4, "sand.frictionAngel",
                "unknown key; did you mean 'frictionAngle'? (required, missing)");
    // Case only (endtime for endTime), at the top level.
    const Dictionary c = parse("deltaT: 1e-4\nendtime: 0.5\n");
    expectError([&] { c.getScalar("endTime"); }, 2, "endtime", "did you mean 'endTime'?");
    // Not a typo: too far (3 edits), too short for 2 edits, or a key already read.
    const Dictionary far = parse("a: 1\nendTyme2x: 2\n");
    expectError([&] { far.getScalar("endTime"); }, 1, "endTime", "missing required key");
    const Dictionary shortKeys = parse("a: 1\nnu: 2\n");
    expectError([&] { shortKeys.getScalar("E"); }, 1, "E", "missing required key");
    const Dictionary read = parse("a: 1\nstartTime: 0\n");
    read.getScalar("startTime");
    expectError([&] { read.getScalar("startTim"); }, 1, "startTim", "missing required key");
    // A key of the model's schema is valid, even before it is read.
    const Dictionary schema = parse("a: 1\nmin: 0\n");
    schema.setKeyHelp({"box", {"min", "max"}, "mpmFoam -list regions"});
    expectError([&] { schema.getVector("mix"); }, 1, "mix", "missing required key");
}

TEST(Dictionary, WrongTypes) {
    const Dictionary d = parse("a: abc\n"
                               "b: [1, 2]\n"
                               "c:\n"
                               "  x: 1\n"
                               "d:\n"
                               "e: 1.5.3\n"
                               "f: 0x10\n");
    expectError([&] { d.getScalar("a"); }, 1, "a", "expected a number, got 'abc'");
    expectError([&] { d.getScalar("b"); }, 2, "b", "expected a number, got a sequence");
    expectError([&] { d.getScalar("c"); }, 4, "c", "expected a number, got a map");
    expectError([&] { d.getScalar("d"); }, 5, "d", "expected a number, got an empty value");
    expectError([&] { d.getScalar("e"); }, 6, "e", "expected a number, got '1.5.3'");
    expectError([&] { d.getScalar("f"); }, 7, "f", "expected a number, got '0x10'");
    expectError([&] { d.getString("b"); }, 2, "b", "expected a string, got a sequence");
    expectError([&] { d.getVector("a"); }, 1, "a", "expected a sequence of numbers");
}

TEST(Dictionary, ScalarRejectsNonFiniteText) {
    const Dictionary d = parse("a: nan\nb: inf\nc: .inf\nd: -Infinity\ne: 1e999\nf: .NaN\n");
    for (const char* key : {"a", "b", "c", "d", "e", "f"}) {
        EXPECT_THROW(d.getScalar(key), InputError) << key;
    }
    expectError([&] { d.getScalar("a"); }, 1, "a", "expected a number, got 'nan'");
}

TEST(Dictionary, IntVersusFloat) {
    const Dictionary d = parse("a: 2.5\nb: 3\nc: 3.0\nd: 1e20\ne: abc\nf: -4\n");
    expectError([&] { d.getInt("a"); }, 1, "a", "expected an integer, got '2.5'");
    EXPECT_EQ(d.getInt("b"), 3);
    EXPECT_EQ(d.getInt("c"), 3);
    expectError([&] { d.getInt("d"); }, 4, "d", "out of range");
    expectError([&] { d.getInt("e"); }, 5, "e", "expected an integer, got 'abc'");
    EXPECT_EQ(d.getInt("f"), -4);
    expectError([&] { d.getInt("f", Bounds::nonNegative()); }, 6, "f",
                "expected an integer in [0, inf], got -4");
    // A scalar entry may be written as an integer.
    EXPECT_DOUBLE_EQ(d.getScalar("b"), 3.0);
}

TEST(Dictionary, OutOfBounds) {
    const Dictionary d = parse("E: -5\nnu: 0.5\nzero: 0\nbig: 1e-3\n");
    expectError([&] { d.getScalar("E", Bounds::positive()); }, 1, "E",
                "expected a number in (0, inf], got -5");
    expectError([&] { d.getScalar("nu", Bounds::halfOpen(-1.0, 0.5)); }, 2, "nu",
                "expected a number in [-1, 0.5), got 0.5");
    EXPECT_DOUBLE_EQ(d.getScalar("nu", Bounds::closed(-1.0, 0.5)), 0.5);
    expectError([&] { d.getScalar("zero", Bounds::positive()); }, 3, "zero", "(0, inf]");
    EXPECT_DOUBLE_EQ(d.getScalar("zero", Bounds::nonNegative()), 0.0);
    expectError([&] { d.getScalar("big", Bounds::closed(0.01, 0.1)); }, 4, "big",
                "expected a number in [0.01, 0.1], got 1e-3");
    expectError(
        [&] {
            d.getScalar("E", {-1.0, 1.0, false, false});
        },
        1, "E", "expected a number in (-1, 1), got -5");
}

TEST(Dictionary, UnknownWord) {
    const Dictionary d = parse("scheme: USX\nmap: {a: 1}\n");
    expectError(
        [&] {
            d.getWord("scheme", {"USF", "USL"});
        },
        1, "scheme", "expected one of USF, USL; got 'USX'");
    expectError(
        [&] {
            d.getWord("map", {"USF", "USL"});
        },
        2, "map", "expected one of USF, USL; got a map");
}

TEST(Dictionary, VectorWrongSize) {
    const Dictionary d = parse("g: [0, -9.81]\nh: [1, two, 3]\ns: 5\n");
    expectError([&] { d.getVector("g", 3); }, 1, "g", "expected a sequence of 3 numbers");
    EXPECT_EQ(d.getVector("g", 2).size(), 2u);
    expectError([&] { d.getVector("h", 3); }, 2, "h", "expected a number at index 1, got 'two'");
    expectError([&] { d.getVector("s", 1); }, 3, "s", "expected a sequence of 1 numbers");
}

TEST(Dictionary, UnknownKeyWithSuggestion) {
    const Dictionary d = parse("grid:\n"
                               "  cellSize: 0.1\n"
                               "  origin: [0, 0, 0]\n"
                               "  cellSzie: 0.2\n"
                               "  extra: 1\n");
    const Dictionary grid = d.subDict("grid");
    grid.getScalar("cellSize");
    grid.getVector("origin", 3);
    grid.getScalarOr("padding", 1.0);
    // Only the first unknown key (in file order) is reported.
    expectError([&] { grid.checkUnknownKeys(); }, 4, "grid.cellSzie",
                "unknown key; did you mean 'cellSize'?");
    grid.has("cellSzie");
    expectError([&] { grid.checkUnknownKeys(); }, 5, "grid.extra", "unknown key; did you mean");
    // The top level read 'grid' and is complete; sub-dictionaries are not checked from it.
    EXPECT_NO_THROW(d.checkUnknownKeys());
}

TEST(Dictionary, UnknownTopLevelKey) {
    const Dictionary d = parse("endTime: 1\nwriteInterval: 0.1\ndeltaT: 0.001\n");
    d.getScalar("endTime");
    d.getScalar("writeInterval");
    d.getScalarOr("deltaTime", 1e-3);
    expectError([&] { d.checkUnknownKeys(); }, 3, "deltaT",
                "unknown key; did you mean 'deltaTime'?");
}

TEST(Dictionary, CopiesShareTheRecordOfReadKeys) {
    const Dictionary d = parse("a: 1\n");
    const Dictionary copy = d; // NOLINT(performance-unnecessary-copy-initialization)
    copy.getScalar("a");
    EXPECT_NO_THROW(d.checkUnknownKeys());
}

TEST(Dictionary, ErrorAndLine) {
    const Dictionary d = parse("a: 1\n"
                               "\n"
                               "b:\n"
                               "  c: 2\n"
                               "e:\n"
                               "f: 3\n");
    EXPECT_EQ(d.line("a"), 1);
    EXPECT_EQ(d.line("b"), 4); // the value (a map) starts on the next line
    EXPECT_EQ(d.line("e"), 5); // an empty value is placed at its key
    EXPECT_EQ(d.line("absent"), 1);
    expectError([&] { d.error("f", "custom problem"); }, 6, "f", "custom problem");
    const Dictionary b = d.subDict("b");
    EXPECT_EQ(b.line("c"), 4);
    expectError([&] { b.error("c", "bad c"); }, 4, "b.c", "bad c");
    expectError([&] { b.error("zz", "no zz"); }, 4, "b.zz", "no zz");
}

TEST(Dictionary, MessageFormat) {
    const Dictionary d = Dictionary::fromString("grid:\n  cellSize: abc\n", "constant/grid");
    const InputError e = catchInputError([&] { d.subDict("grid").getScalar("cellSize"); });
    EXPECT_STREQ(e.what(), "constant/grid:2: key 'grid.cellSize': expected a number, got 'abc'");
}

// Loading

TEST(Dictionary, SyntaxErrorLineNumber) {
    expectError([] { parse("a: 1\nb: 2\nc: [1, 2\nd: 4\n"); }, 4, "", "YAML syntax error");
    expectError([] { parse("a: 1\nb: {x: 1\n"); }, 3, "", "YAML syntax error");
    const InputError e = catchInputError([] { parse("a: 1\n  b: 2\n"); });
    EXPECT_EQ(e.line(), 2) << e.what();
    EXPECT_EQ(e.key(), "");
    EXPECT_NE(std::string(e.what()).find("YAML syntax error: "), std::string::npos);
}

TEST(Dictionary, DuplicateKey) {
    expectError([] { parse("a: 1\nb: 2\na: 3\n"); }, 3, "a", "duplicate key");
    expectError([] { parse("grid:\n  x: 1\n  x: 2\n"); }, 3, "grid.x", "duplicate key");
    expectError([] { parse("regions:\n  - {t: 1, t: 2}\n"); }, 2, "regions[0].t", "duplicate key");
}

TEST(Dictionary, ComplexOrEmptyKeysAreErrors) {
    expectError([] { parse("? [1, 2]\n: 5\n"); }, 1, "", "expected a plain name as key");
    expectError([] { parse("a:\n  ? {x: 1}\n  : 5\n"); }, 2, "a", "expected a plain name as key");
    expectError([] { parse("~: 5\n"); }, 1, "", "expected a plain name as key");
}

TEST(Dictionary, TopLevelMustBeAMap) {
    expectError([] { parse("- 1\n- 2\n"); }, 1, "", "expected a map");
    expectError([] { parse("just text\n"); }, 1, "", "expected a map");
}

/// An OpenFOAM controlDict as a user would paste it: banner, FoamFile header, entries.
const char* const openFoamControlDict =
    "/*--------------------------------*- C++ -*----------------------------------*\\\n"
    "  =========                 |\n"
    "  \\\\      /  F ield         | OpenFOAM: The Open Source CFD Toolbox\n"
    "\\*---------------------------------------------------------------------------*/\n"
    "FoamFile\n"
    "{\n"
    "    version     2.0;\n"
    "    format      ascii;\n"
    "    class       dictionary;\n"
    "    object      controlDict;\n"
    "}\n"
    "// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //\n"
    "\n"
    "application     icoFoam;\n"
    "\n"
    "endTime         0.5;\n";

TEST(Dictionary, OpenFoamSyntaxIsRecognised) {
    // The header is skipped: the message names the first entry, its line and its YAML form.
    expectError([] { parse(openFoamControlDict); }, 14, "application",
                "write 'application icoFoam;' as 'application: icoFoam'");
    expectError([] { parse(openFoamControlDict); }, 14, "application", "docs/caseFormat.md");
    expectError([] { parse(openFoamControlDict); }, 14, "application", "are YAML");
    // Without a header, `word value;` lines are enough; vectors become YAML sequences.
    expectError([] { parse("endTime 0.5;\ndeltaT 1e-4;\n"); }, 1, "endTime",
                "write 'endTime 0.5;' as 'endTime: 0.5'");
    expectError([] { parse("// gravity\nvalue (0 -9.81 0);\n"); }, 2, "value",
                "as 'value: [0, -9.81, 0]'");
    // A sub-dictionary first, its brace on the next line (OpenFOAM's layout).
    expectError([] { parse("FoamFile { version 2.0; }\nboundary\n{\n  yMin noSlip;\n}\n"); }, 2,
                "boundary", "write the sub-dictionary 'boundary { … }' as 'boundary:'");
    // A YAML syntax error that is not OpenFOAM's form keeps the YAML message.
    expectError([] { parse("a: 1\nb: {x: 1\n"); }, 3, "", "YAML syntax error");
    expectError([] { parse("just text\n"); }, 1, "", "expected a map");
}

TEST_F(DictionaryFile, OpenFoamFileNamesFileAndLine) {
    const std::filesystem::path p = file(openFoamControlDict);
    expectError([&] { Dictionary::fromFile(p, "system/controlDict"); }, 14, "application",
                "'application: icoFoam'", "system/controlDict");
}

TEST(Dictionary, SingleDocumentOnly) {
    expectError([] { parse("a: 1\n---\nb: 2\n"); }, 3, "", "single YAML document");
}

TEST_F(DictionaryFile, FromFile) {
    const Dictionary d =
        Dictionary::fromFile(file("# header\nrho: 1000\nmu: oops\n"), "constant/materials");
    EXPECT_EQ(d.fileName(), "constant/materials");
    EXPECT_EQ(d.path(), "");
    EXPECT_DOUBLE_EQ(d.getScalar("rho"), 1000.0);
    expectError([&] { d.getScalar("mu"); }, 3, "mu", "expected a number, got 'oops'",
                "constant/materials");
}

TEST_F(DictionaryFile, FromEmptyFile) {
    const Dictionary d = Dictionary::fromFile(file(""), "system/control");
    EXPECT_TRUE(d.keys().empty());
    EXPECT_NO_THROW(d.checkUnknownKeys());
}

TEST_F(DictionaryFile, FromFileSyntaxError) {
    const std::filesystem::path f = file("a: 1\nb: [\n");
    expectError([&] { Dictionary::fromFile(f, "system/control"); }, 3, "", "YAML syntax error",
                "system/control");
}

TEST_F(DictionaryFile, MissingFile) {
    const std::filesystem::path missing = dir_ / "does_not_exist.yaml";
    expectError([&] { Dictionary::fromFile(missing, "system/control"); }, 0, "", "cannot open file",
                "system/control");
    expectError([&] { Dictionary::fromFile(dir_, "dir"); }, 0, "", "cannot open file", "dir");
}

/// True if `text` has no byte a terminal could take for a control or an invalid character:
/// only printable ASCII and '\n' (the corrupted files below hold no valid multi-byte UTF-8).
bool plainAscii(const std::string& text) {
    for (const char c : text) {
        const auto b = static_cast<unsigned char>(c);
        if ((b < 0x20 && b != '\n') || b >= 0x7f) return false;
    }
    return true;
}

TEST_F(DictionaryFile, CorruptedBytesAreEscapedInMessages) {
    // A quoted value with an invalid byte and control bytes (ESC, SOH, DEL, CR).
    const Dictionary d = Dictionary::fromFile(
        file(std::string("rho: \"2\xff\x1b[2J\x01\x7f\r\"\nrh\xfeo: 1\n")), "constant/materials");
    const InputError value = catchInputError([&] { d.getScalar("rho"); });
    EXPECT_TRUE(plainAscii(value.what())) << value.what();
    EXPECT_NE(std::string(value.what()).find("got '2\\xff\\x1b[2J\\x01\\x7f\\x0d'"),
              std::string::npos)
        << value.what();
    // An unknown key is named escaped in the message, as written in key().
    const InputError key = catchInputError([&] { d.checkUnknownKeys(); });
    EXPECT_TRUE(plainAscii(key.what())) << key.what();
    EXPECT_NE(std::string(key.what()).find("key 'rh\\xfeo'"), std::string::npos) << key.what();
    EXPECT_EQ(key.key(), "rh\xfeo");
}

TEST_F(DictionaryFile, YamlParserMessagesAreEscaped) {
    // yaml-cpp quotes the character after a backslash in its message.
    const std::filesystem::path f = file(std::string("a: 1\nb: \"x\\\xff\"\n"));
    const InputError e = catchInputError([&] { Dictionary::fromFile(f, "system/controlDict"); });
    EXPECT_EQ(e.line(), 2) << e.what();
    EXPECT_TRUE(plainAscii(e.what())) << e.what();
    EXPECT_NE(std::string(e.what()).find("\\xff"), std::string::npos) << e.what();
    // Control bytes where YAML expects structure.
    const std::filesystem::path g = file("a: [1, \x01\x02\xff\n");
    const InputError e2 = catchInputError([&] { Dictionary::fromFile(g, "system/controlDict"); });
    EXPECT_TRUE(plainAscii(e2.what())) << e2.what();
}

TEST_F(DictionaryFile, ValidUtf8StaysReadable) {
    const Dictionary d = Dictionary::fromFile(file("angle: 30\xc2\xb0 \xce\xbc\n"), "m");
    const InputError e = catchInputError([&] { d.getScalar("angle"); });
    EXPECT_NE(std::string(e.what()).find("got '30\xc2\xb0 \xce\xbc'"), std::string::npos)
        << e.what();
}

TEST(Dictionary, EditDistance) {
    EXPECT_EQ(editDistance("", ""), 0);
    EXPECT_EQ(editDistance("abc", ""), 3);
    EXPECT_EQ(editDistance("", "abc"), 3);
    EXPECT_EQ(editDistance("kitten", "sitting"), 3);
    EXPECT_EQ(editDistance("cellSize", "cellSzie"), 2);
    EXPECT_EQ(editDistance("same", "same"), 0);
}

} // namespace
} // namespace mpm
