// SPDX-License-Identifier: GPL-3.0-or-later
// The run-time selection tables (case/Registry.hpp): one registration for both dimensions, a
// declared dimension that the other refuses with a generated message, a name registered twice
// reported as an internal error, and every create checking the keys its model did not read.
#include "case/Registry.hpp"
#include "case/Selection.hpp"

#include "TestSupport.hpp"
#include "contact/CouplingLaw.hpp"
#include "particles/Region.hpp"
#include "rigid/Shape.hpp"
#include "solver/StressUpdateOrder.hpp"
#include "transfers/AntiLocking.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace mpm {
namespace {

/// A model of test families: reads `a` only, and never checks its keys itself.
template <int dim> struct Part {
    explicit Part(const Dictionary& d) { d.getScalarOr("a", 0.0); }
    virtual ~Part() = default;
};
template <int dim> using PartRegistry = Registry<Part<dim>>;

MPM_FAMILY_INFO("testParts", {"nowhere", "99. tests", {{"type", "word", "-", "required", "-"}}});
MPM_FAMILY(PartRegistry<2>, 2, "testParts");
MPM_FAMILY(PartRegistry<3>, 3, "testParts");
MPM_REGISTER_DIMS(PartRegistry, Part, "both");
MPM_REGISTER_ONLY(3, PartRegistry, Part<3>, "solid");
MPM_SCHEMA("testParts", "solid", {"a 3D part", {}, "{type: solid}", "in 2D use 'both'"});
MPM_REGISTER_ONLY(2, PartRegistry, Part<2>, "flat");

/// A family with one name registered twice.
template <int dim> struct Twice {
    explicit Twice(const Dictionary&) {}
    virtual ~Twice() = default;
};
using TwiceRegistry = Registry<Twice<2>>;
MPM_FAMILY_INFO("testTwice", {"nowhere", "99. tests", {}});
MPM_FAMILY(TwiceRegistry, 2, "testTwice");
MPM_REGISTER(TwiceRegistry, Twice<2>, "again");
MPM_REGISTER(TwiceRegistry, Twice<2>, "again");

/// A registry no MPM_FAMILY joins.
struct Orphan {
    explicit Orphan(const Dictionary&) {}
    virtual ~Orphan() = default;
};
MPM_REGISTER(Registry<Orphan>, Orphan, "orphan");

Dictionary dict(const std::string& yaml) {
    return Dictionary::fromString(yaml, "constant/test");
}

std::string joined(const std::vector<std::string>& lines) {
    std::string all;
    for (const auto& l : lines)
        all += l + '\n';
    return all;
}

TEST(Registry, OneLineRegistersBothDimensions) {
    EXPECT_TRUE(PartRegistry<2>::table().count("both"));
    EXPECT_TRUE(PartRegistry<3>::table().count("both"));
    EXPECT_NO_THROW(PartRegistry<2>::create(dict("{type: both, a: 1}")));
    EXPECT_NO_THROW(PartRegistry<3>::create(dict("{type: both}")));
}

TEST(Registry, TheOtherDimensionRefusesATypeOfOneWithAGeneratedMessage) {
    EXPECT_NO_THROW(PartRegistry<3>::create(dict("{type: solid}")));
    const InputError e =
        test::catchInputError([] { PartRegistry<2>::create(dict("{type: solid}")); });
    EXPECT_EQ(e.key(), "type");
    EXPECT_NE(std::string(e.what()).find("'solid' is 3D only (this case is 2D); in 2D use 'both'"),
              std::string::npos)
        << e.what();
    const InputError f =
        test::catchInputError([] { PartRegistry<3>::create(dict("{type: flat}")); });
    EXPECT_NE(std::string(f.what()).find("'flat' is 2D only (this case is 3D)"), std::string::npos)
        << f.what();
    // A refused type is not offered as a valid one.
    const InputError g = test::catchInputError([] { PartRegistry<2>::create(dict("{type: x}")); });
    EXPECT_EQ(std::string(g.what()).find("solid"), std::string::npos) << g.what();

    const auto* family = ModelCatalogue::find("testParts");
    ASSERT_NE(family, nullptr);
    EXPECT_EQ(ModelCatalogue::onlyDim(*family, "solid"), 3);
    EXPECT_EQ(ModelCatalogue::onlyDim(*family, "flat"), 2);
    EXPECT_EQ(ModelCatalogue::onlyDim(*family, "both"), 0);
    EXPECT_TRUE(ModelCatalogue::problems(*family).empty())
        << joined(ModelCatalogue::problems(*family));
}

TEST(Registry, TheRealRegistriesDeclareTheirDimensions) {
    // Regions, shapes and contact laws refuse their one-dimensional types.
    const InputError e = test::catchInputError(
        [] { Region<2>::create(dict("{type: sphere, centre: [0, 0], radius: 1}")); });
    EXPECT_NE(std::string(e.what()).find("'sphere' is 3D only (this case is 2D); use 'disk' in 2D"),
              std::string::npos)
        << e.what();
    const InputError f =
        test::catchInputError([] { Shape<2>::create(dict("{type: levelSet, file: x.vti}")); });
    EXPECT_NE(std::string(f.what()).find("'levelSet' is 3D only (this case is 2D)"),
              std::string::npos)
        << f.what();
    for (const auto* family : ModelCatalogue::families()) {
        if (family->name.compare(0, 4, "test") == 0) continue;
        EXPECT_TRUE(ModelCatalogue::problems(*family).empty())
            << joined(ModelCatalogue::problems(*family));
    }
}

TEST(Registry, ANameRegisteredTwiceIsAnInternalError) {
    const auto* family = ModelCatalogue::find("testTwice");
    ASSERT_NE(family, nullptr);
    const std::string problems = joined(ModelCatalogue::problems(*family));
    EXPECT_NE(problems.find("family 'testTwice': 'again' is registered twice in 2D"),
              std::string::npos)
        << problems;
    EXPECT_THROW(ModelCatalogue::check(), std::logic_error);
    try {
        TwiceRegistry::create(dict("{type: again}"));
        ADD_FAILURE() << "expected a std::logic_error";
    } catch (const std::logic_error& e) {
        EXPECT_NE(std::string(e.what()).find("'testTwice' has 'again' registered twice"),
                  std::string::npos)
            << e.what();
    }
}

TEST(Registry, ARegistryWithoutFamilyIsAnInternalError) {
    EXPECT_THROW(Registry<Orphan>::create(dict("{type: orphan}")), std::logic_error);
}

TEST(Registry, CreateReportsAKeyTheModelDidNotRead) {
    // Part never calls checkUnknownKeys: create does, for every family.
    const InputError e =
        test::catchInputError([] { PartRegistry<2>::create(dict("{type: both, b: 1}")); });
    EXPECT_EQ(e.key(), "b");
    // A real family whose models relied on their callers: a coupling law through its registry.
    const InputError f = test::catchInputError([] {
        CouplingLawRegistry<2>::create(dict("{type: barrier, friction: 0.1, stifness: 1}"), 0.01);
    });
    EXPECT_EQ(f.key(), "stifness");
}

TEST(Registry, AWordAmongOtherKeysSelectsAnOption) {
    // `part: both` in a map of other keys: selectByWord reads that key only.
    const Dictionary d = dict("{part: both, other: 1}");
    EXPECT_NO_THROW(selectByWord<PartRegistry<2>>(d, "part", "flat"));
    EXPECT_EQ(d.readKeys().count("other"), 0u);
    // Absent: the default; absent and required (no default): an InputError at the key.
    EXPECT_NO_THROW(selectByWord<PartRegistry<2>>(dict("{other: 1}"), "part", "both"));
    const InputError missing = test::catchInputError(
        [] { selectByWord<PartRegistry<2>>(dict("{other: 1}"), "part", ""); });
    EXPECT_EQ(missing.key(), "part");
    // An unknown word lists the registered ones (not the other dimension's refused 'solid').
    const InputError e = test::catchInputError(
        [] { selectByWord<PartRegistry<2>>(dict("{part: x}"), "part", "both"); });
    EXPECT_EQ(e.key(), "part");
    EXPECT_NE(std::string(e.what()).find("expected one of both, flat; got 'x'"), std::string::npos)
        << e.what();
    // A default that is not registered, or a registry without family: internal errors.
    EXPECT_THROW(selectByWord<PartRegistry<2>>(dict("{}"), "part", "none"), std::logic_error);
    EXPECT_THROW(selectByWord<Registry<Orphan>>(dict("{w: orphan}"), "w", ""), std::logic_error);
    EXPECT_THROW(selectByWord<TwiceRegistry>(dict("{w: again}"), "w", ""), std::logic_error);
}

TEST(Registry, TheWordsOfTheSchemesSelectThroughTheirRegistries) {
    const InputError e = test::catchInputError(
        [] { StressUpdateOrder::create(dict("{stressUpdate: USX, kernel: linear}")); });
    EXPECT_EQ(e.key(), "stressUpdate");
    EXPECT_NE(std::string(e.what()).find("expected one of MUSL, USF, USL; got 'USX'"),
              std::string::npos)
        << e.what();
    EXPECT_TRUE(StressUpdateOrder::create(dict("{kernel: linear}"))->gradientInGridToParticle());
    EXPECT_TRUE(StressUpdateOrder::create(dict("{stressUpdate: USF}"))->gradientBeforeUpdate());
    const InputError f =
        test::catchInputError([] { AntiLocking<3>::create(dict("{antiLocking: Fbar}")); });
    EXPECT_EQ(f.key(), "antiLocking");
    EXPECT_NE(std::string(f.what()).find("expected one of fBar, none; got 'Fbar'"),
              std::string::npos)
        << f.what();
    EXPECT_NO_THROW(AntiLocking<2>::create(dict("{}")));
}

} // namespace
} // namespace mpm
