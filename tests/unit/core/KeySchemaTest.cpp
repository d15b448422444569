// SPDX-License-Identifier: GPL-3.0-or-later
// The key schemas (core/KeySchema.hpp): every registered type has one, every key it declares is
// in docs/caseFormat.md and in `mpmFoam -list`, the models read no key they do not declare, and
// the unknown-key and unknown-type messages come from the same table.
#include "core/KeySchema.hpp"

#include "TestSupport.hpp"
#include "boundary/BoundaryCondition.hpp"
#include "boundary/FaceKind.hpp"
#include "case/Registry.hpp"
#include "contact/BodyContact.hpp"
#include "contact/CouplingLaw.hpp"
#include "forces/BodyAcceleration.hpp"
#include "kernels/Kernels.hpp"
#include "materials/Material.hpp"
#include "monitors/FunctionObject.hpp"
#include "particles/Region.hpp"
#include "rigid/Shape.hpp"
#include "solver/StressUpdateOrder.hpp"
#include "transfers/AntiLocking.hpp"
#include "transfers/Transfer.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#ifndef MPMFOAM_CASE_FORMAT
#error "MPMFOAM_CASE_FORMAT (the path of docs/caseFormat.md) must be defined by the build"
#endif

namespace mpm {
namespace {

// A family of this test only: a type with a schema and one without (the fallback of -list and
// of the unknown-key message).
struct Dummy {
    explicit Dummy(const Dictionary& d) { d.getScalarOr("a", 0.0); }
    virtual ~Dummy() = default;
};
using DummyRegistry = Registry<Dummy>;
const std::string testFamily = "testOnlyFamily";
MPM_FAMILY_INFO("testOnlyFamily",
                {"nowhere", "99. tests", {{"type", "word", "-", "required", "the type"}}});
MPM_FAMILY(DummyRegistry, 2, "testOnlyFamily");
MPM_REGISTER(DummyRegistry, Dummy, "described");
MPM_REGISTER(DummyRegistry, Dummy, "undescribed");
MPM_SCHEMA("testOnlyFamily", "described",
           {"a test type", {{"a", "scalar", "m", "0", "a length"}}, "{type: described}"});

/// The real families (the unit tests' own, named test…, left out).
std::vector<const ModelCatalogue::Family*> realFamilies() {
    std::vector<const ModelCatalogue::Family*> out;
    for (const auto* f : ModelCatalogue::families())
        if (f->name.compare(0, 4, "test") != 0) out.push_back(f);
    return out;
}

/// The registered types of `f` but those unit tests register (named test…).
std::map<std::string, std::set<int>> realTypes(const ModelCatalogue::Family& f) {
    auto types = ModelCatalogue::types(f);
    for (auto it = types.begin(); it != types.end();)
        it = it->first.compare(0, 4, "test") == 0 ? types.erase(it) : std::next(it);
    return types;
}

std::string readFile(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// The text of `## <heading>` of docs/caseFormat.md up to the next `## ` heading.
std::string docSection(const std::string& doc, const std::string& heading) {
    const std::string start = "\n## " + heading + "\n";
    const auto b = doc.find(start);
    if (b == std::string::npos) return "";
    const auto e = doc.find("\n## ", b + start.size());
    return doc.substr(b, e == std::string::npos ? std::string::npos : e - b);
}

std::string listOutput(const std::string& family = "") {
    std::ostringstream os;
    ModelCatalogue::list(os, family);
    return os.str();
}

TEST(KeySchema, EveryFamilyOfTheSolverIsInTheCatalogue) {
    std::set<std::string> names;
    for (const auto* f : realFamilies()) {
        names.insert(f->name);
        EXPECT_FALSE(f->info.where.empty()) << f->name;
        EXPECT_FALSE(f->info.docSection.empty()) << f->name;
        EXPECT_FALSE(ModelCatalogue::types(*f).empty()) << f->name << " has no types";
    }
    const std::set<std::string> expected{"materials",
                                         "regions",
                                         "boundaryConditions",
                                         "bodyAccelerations",
                                         "couplingLaws",
                                         "bodyContact",
                                         "shapes",
                                         "functionObjects",
                                         "kernels",
                                         "transfers",
                                         "stressUpdateOrders",
                                         "antiLocking",
                                         "initialVelocity",
                                         "initialStress",
                                         "seedingMethods",
                                         "bodyMotions",
                                         "decompositionMethods",
                                         "backends"};
    EXPECT_EQ(names, expected);
}

TEST(KeySchema, EveryRegisteredTypeHasASchema) {
    for (const auto* f : realFamilies())
        for (const auto& [type, dims] : realTypes(*f)) {
            EXPECT_TRUE(f->schemas.count(type))
                << f->name << " type '" << type << "' has no schema";
            if (f->schemas.count(type)) {
                const TypeSchema& s = f->schemas.at(type);
                EXPECT_FALSE(s.summary.empty()) << f->name << '.' << type;
                EXPECT_FALSE(s.example.empty()) << f->name << '.' << type;
                if (const int only = ModelCatalogue::onlyDim(*f, type)) {
                    EXPECT_EQ(dims, std::set<int>{only}) << f->name << '.' << type;
                }
            }
        }
    // No schema for a type that is not registered (a misspelt name would never be used).
    for (const auto* f : realFamilies()) {
        const auto types = realTypes(*f);
        for (const auto& [type, schema] : f->schemas)
            EXPECT_TRUE(types.count(type))
                << f->name << ": schema of unregistered '" << type << "'";
    }
}

TEST(KeySchema, EveryKeyAndTypeIsInCaseFormatMd) {
    const std::string doc = readFile(MPMFOAM_CASE_FORMAT);
    ASSERT_FALSE(doc.empty()) << "cannot read " << MPMFOAM_CASE_FORMAT;
    for (const auto* f : realFamilies()) {
        const std::string section = docSection(doc, f->info.docSection);
        ASSERT_FALSE(section.empty())
            << f->name << ": no section '## " << f->info.docSection << "' in docs/caseFormat.md";
        // `name`, or the last part of a dotted path (`transfer.ratio`).
        const auto quoted = [&](const std::string& name) {
            return section.find("`" + name + "`") != std::string::npos ||
                   section.find("." + name + "`") != std::string::npos;
        };
        for (const KeyInfo& k : f->info.common)
            EXPECT_TRUE(quoted(k.name)) << "docs/caseFormat.md §" << f->info.docSection
                                        << " lacks `" << k.name << "` (" << f->name << ")";
        for (const auto& [type, schema] : f->schemas) {
            EXPECT_TRUE(quoted(type)) << "docs/caseFormat.md §" << f->info.docSection << " lacks `"
                                      << type << "` (" << f->name << ")";
            for (const KeyInfo& k : schema.keys)
                EXPECT_TRUE(quoted(k.name))
                    << "docs/caseFormat.md §" << f->info.docSection << " lacks `" << k.name << "` ("
                    << f->name << '.' << type << ")";
        }
    }
}

/// A line of `text` that holds the key's row: name, type, unit, default and meaning, in order.
bool hasRow(const std::string& text, const KeyInfo& k) {
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        std::size_t at = 0;
        bool ok = line.compare(0, 4, "    ") == 0;
        for (const std::string* cell : {&k.name, &k.type, &k.unit, &k.deflt, &k.meaning}) {
            if (!ok) break;
            at = line.find(*cell, at);
            ok = at != std::string::npos;
            if (ok) at += cell->size();
        }
        if (ok) return true;
    }
    return false;
}

TEST(KeySchema, ListShowsEveryTypeWithItsKeysDefaultsAndUnits) {
    const std::string all = listOutput();
    for (const auto* f : realFamilies()) {
        const std::string one = listOutput(f->name);
        EXPECT_NE(all.find(one.substr(one.find(f->name + ", selected by"))), std::string::npos)
            << "-list " << f->name << " is not the family's part of -list";
        EXPECT_NE(one.find("docs/caseFormat.md §" + f->info.docSection), std::string::npos);
        for (const KeyInfo& k : f->info.common)
            EXPECT_TRUE(hasRow(one, k)) << "-list " << f->name << " lacks the row of " << k.name;
        for (const auto& [type, dims] : realTypes(*f)) {
            EXPECT_NE(one.find("\n  " + type + " ("), std::string::npos) << f->name << '.' << type;
            for (const KeyInfo& k : f->schemas.at(type).keys)
                EXPECT_TRUE(hasRow(one, k))
                    << "-list " << f->name << " lacks the row of " << type << '.' << k.name;
        }
        // Another family's types are not in this family's list.
        for (const auto* g : realFamilies())
            if (g != f) {
                EXPECT_EQ(one.find(g->name + ", selected by"), std::string::npos);
            }
    }
    EXPECT_THROW(listOutput("material"), std::invalid_argument);
}

TEST(KeySchema, ATypeWithoutSchemaPointsToTheDocumentation) {
    const std::string list = listOutput(testFamily);
    EXPECT_NE(list.find("undescribed (2D): its keys are documented in docs/caseFormat.md §99. "
                        "tests"),
              std::string::npos)
        << list;
    EXPECT_NE(list.find("described (2D): a test type"), std::string::npos) << list;
    const Dictionary d = Dictionary::fromString("{type: undescribed, b: 1}", "test");
    const InputError e = test::catchInputError([&] { DummyRegistry::create(d); });
    EXPECT_NE(std::string(e.what()).find(
                  "The keys of undescribed are described in docs/caseFormat.md §99. tests"),
              std::string::npos)
        << e.what();
}

TEST(KeySchema, UnknownKeyMessageListsTheSchemasKeys) {
    const Dictionary d = Dictionary::fromString(
        "{type: linearElastic, density: 1000, E: 1.0e6, nu: 0.3, densty: 1}", "constant/materials");
    const auto m = Material<2>::create;
    const InputError e = test::catchInputError([&] { m(d, "soil"); });
    EXPECT_EQ(e.key(), "densty");
    EXPECT_NE(std::string(e.what()).find("did you mean 'density'? The keys of linearElastic are: "
                                         "type, density, E, nu (mpmFoam -list materials)"),
              std::string::npos)
        << e.what();

    // The suggestion may be a key of the schema that this input did not make the model read.
    const Dictionary t = Dictionary::fromString("{type: described, aa: 1}", "test");
    const InputError f = test::catchInputError([&] { DummyRegistry::create(t); });
    EXPECT_NE(std::string(f.what()).find("did you mean 'a'? The keys of described are: type, a"),
              std::string::npos)
        << f.what();

    // An unknown type points to the list of the family.
    const InputError g = test::catchInputError(
        [] { Material<3>::create(Dictionary::fromString("{type: linearElastik}", "m"), "soil"); });
    EXPECT_NE(std::string(g.what()).find("(mpmFoam -list materials shows their keys)"),
              std::string::npos)
        << g.what();
}

/// Build a model of `family` from `dict` in dimension `dim` through its registry.
using Creator = std::function<void(int dim, const Dictionary& dict)>;
const std::map<std::string, Creator>& creators() {
    static const std::map<std::string, Creator> c{
        {"materials",
         [](int dim, const Dictionary& d) {
             dim == 2 ? (void)MaterialRegistry<2>::create(d, "m")
                      : (void)MaterialRegistry<3>::create(d, "m");
         }},
        {"regions",
         [](int dim, const Dictionary& d) {
             dim == 2 ? (void)Registry<Region<2>>::create(d) : (void)Registry<Region<3>>::create(d);
         }},
        {"boundaryConditions",
         [](int dim, const Dictionary& d) {
             // open and periodic are face kinds of the set, not conditions (their examples
             // build whole boundaries in tests/unit/boundary/BoundaryConditionsTest.cpp).
             if (faceKind(d.getString("type")) != FaceKind::constrained) return;
             dim == 2 ? (void)BoundaryConditionRegistry<2>::create(d)
                      : (void)BoundaryConditionRegistry<3>::create(d);
         }},
        {"bodyAccelerations",
         [](int dim, const Dictionary& d) {
             dim == 2 ? (void)BodyAccelerationRegistry<2>::create(d)
                      : (void)BodyAccelerationRegistry<3>::create(d);
         }},
        {"couplingLaws",
         [](int dim, const Dictionary& d) {
             dim == 2 ? (void)CouplingLawRegistry<2>::create(d, 0.01)
                      : (void)CouplingLawRegistry<3>::create(d, 0.01);
         }},
        {"bodyContact",
         [](int dim, const Dictionary& d) {
             dim == 2 ? (void)BodyContactRegistry<2>::create(d)
                      : (void)BodyContactRegistry<3>::create(d);
         }},
        {"shapes",
         [](int dim, const Dictionary& d) {
             dim == 2 ? (void)ShapeRegistry<2>::create(d) : (void)ShapeRegistry<3>::create(d);
         }},
        {"functionObjects",
         [](int dim, const Dictionary& d) {
             dim == 2 ? (void)FunctionObjectRegistry<2>::create(d, "f")
                      : (void)FunctionObjectRegistry<3>::create(d, "f");
         }},
    };
    return c;
}

/// The dimension an example is written for: the type's only one, else 2 (the examples' vectors
/// have two components unless the type is 3D only).
int exampleDim(const ModelCatalogue::Family& f, const std::string& type) {
    const int only = ModelCatalogue::onlyDim(f, type);
    return only ? only : 2;
}

TEST(KeySchema, ModelsReadOnlyTheKeysTheirSchemaDeclares) {
    // Built from its example, each model looks up (reads or tests) only declared keys, and the
    // example is a valid dictionary. Types whose example needs more than the dictionary:
    const std::set<std::string> needsFiles{"shapes.levelSet"};
    for (const auto* f : realFamilies()) {
        const auto creator = creators().find(f->name);
        if (creator == creators().end()) continue; // the words of system/mpmSchemes: below
        for (const auto& [type, schema] : f->schemas) {
            const Dictionary d = Dictionary::fromString(schema.example, f->name + "." + type);
            const int dim = exampleDim(*f, type);
            try {
                creator->second(dim, d);
                d.checkUnknownKeys();
            } catch (const InputError& e) {
                EXPECT_TRUE(needsFiles.count(f->name + "." + type))
                    << f->name << '.' << type << " (" << dim << "D): " << e.what();
            }
            const std::optional<KeyList> keys = ModelCatalogue::keys(f->name, type);
            ASSERT_TRUE(keys);
            std::set<std::string> declared;
            for (const KeyInfo& k : *keys)
                declared.insert(k.name);
            for (const std::string& read : d.readKeys())
                EXPECT_TRUE(declared.count(read))
                    << f->name << '.' << type << " reads '" << read << "', not in its schema";
        }
    }
    // Kernels and transfers: their examples are valid system/mpmSchemes lines.
    for (const std::string family : {"kernels", "transfers"})
        for (const auto& [type, schema] : ModelCatalogue::find(family)->schemas) {
            const std::string other =
                family == "kernels" ? "transfer: pic" : "kernel: quadraticBSpline";
            const Dictionary d = Dictionary::fromString(schema.example + "\n" + other, "schemes");
            EXPECT_NO_THROW(Transfer<2>::create(d, 0.25)) << family << '.' << type;
            EXPECT_NO_THROW(d.checkUnknownKeys()) << family << '.' << type;
        }
    // The registered kernels are those of kernels/Kernels.hpp that the unit tests loop over.
    std::set<std::string> kernels;
    for (const auto& [type, dims] : ModelCatalogue::types(*ModelCatalogue::find("kernels")))
        kernels.insert(type);
    const std::vector<std::string> defined = kernelNames();
    EXPECT_EQ(kernels, std::set<std::string>(defined.begin(), defined.end()));
    // Stress-update orders and anti-locking: their examples are valid system/mpmSchemes lines.
    for (const auto& [type, schema] : ModelCatalogue::find("stressUpdateOrders")->schemas) {
        const Dictionary d = Dictionary::fromString(schema.example, "schemes");
        EXPECT_NO_THROW(StressUpdateOrder::create(d)) << type;
        EXPECT_NO_THROW(d.checkUnknownKeys()) << type;
    }
    for (const auto& [type, schema] : ModelCatalogue::find("antiLocking")->schemas) {
        const Dictionary d = Dictionary::fromString(schema.example, "schemes");
        EXPECT_NO_THROW(AntiLocking<2>::create(d)) << type;
        EXPECT_NO_THROW(AntiLocking<3>::create(d)) << type;
        EXPECT_NO_THROW(d.checkUnknownKeys()) << type;
    }
    // A transfer map with a key of another transfer names the keys of its own.
    const Dictionary pic =
        Dictionary::fromString("kernel: linear\ntransfer: {type: pic, ratio: 0.9}", "schemes");
    const InputError e = test::catchInputError([&] { Transfer<2>::create(pic, 0.25); });
    EXPECT_NE(std::string(e.what()).find("The keys of pic are: type (mpmFoam -list transfers)"),
              std::string::npos)
        << e.what();
}

} // namespace
} // namespace mpm
