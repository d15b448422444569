// SPDX-License-Identifier: GPL-3.0-or-later
#include "solver/State.hpp"

#include <gtest/gtest.h>

#include <type_traits>

namespace {

using namespace mpm;

template <int dim> using Materials = std::vector<std::unique_ptr<Material<dim>>>;
template <int dim> using Bodies = std::vector<std::unique_ptr<RigidBody<dim>>>;
template <int dim> using Reactions = std::array<Vec<dim>, 2 * dim>;

template <int dim> void expectNamedConstruction() {
    // No positional list of figures builds a State (a misordered one would compile)...
    EXPECT_FALSE(std::is_aggregate_v<State<dim>>);
    EXPECT_FALSE((std::is_constructible_v<State<dim>, const Particles<dim>&, const Grid<dim>&,
                                          const Materials<dim>&, const Vec<dim>&,
                                          const Reactions<dim>&, const Bodies<dim>&, double, Index,
                                          double, const BodyAcceleration<dim>&, double, double>));
    // ...the references build it, each of a type of its own: two swapped do not.
    EXPECT_TRUE(
        (std::is_constructible_v<State<dim>, const Particles<dim>&, const Grid<dim>&,
                                 const Materials<dim>&, const Vec<dim>&, const Reactions<dim>&,
                                 const Bodies<dim>&, const BodyAcceleration<dim>&>));
    EXPECT_FALSE(
        (std::is_constructible_v<State<dim>, const Particles<dim>&, const Grid<dim>&,
                                 const Materials<dim>&, const Reactions<dim>&, const Vec<dim>&,
                                 const Bodies<dim>&, const BodyAcceleration<dim>&>));
    EXPECT_FALSE(
        (std::is_constructible_v<State<dim>, const Particles<dim>&, const Grid<dim>&,
                                 const Bodies<dim>&, const Vec<dim>&, const Reactions<dim>&,
                                 const Materials<dim>&, const BodyAcceleration<dim>&>));
}

TEST(State, IsBuiltByNamingItsMembers) {
    expectNamedConstruction<2>();
    expectNamedConstruction<3>();
}

} // namespace
