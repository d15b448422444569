// SPDX-License-Identifier: GPL-3.0-or-later
#include "transfers/AntiLocking.hpp"

#include "case/Selection.hpp"

namespace mpm {

MPM_FAMILY_INFO("antiLocking", {"antiLocking in system/mpmSchemes (a word; default none)",
                                "3. system/mpmSchemes",
                                {}});
MPM_FAMILY_DIMS(AntiLockingRegistry, "antiLocking");

namespace {

/// No anti-locking: L_p as the transfer gave it.
template <int dim> class NoAntiLocking final : public AntiLocking<dim> {
public:
    explicit NoAntiLocking(const Dictionary&) {}
    void apply(Particles<dim>&, const Grid<dim>&, const Transfer<dim>&, const BlockSort<dim>&,
               double) override {}
};

} // namespace

MPM_REGISTER_DIMS(AntiLockingRegistry, NoAntiLocking, "none");
MPM_SCHEMA("antiLocking", "none",
           {"no anti-locking: each point keeps its own velocity gradient",
            {},
            "antiLocking: none"});

template <int dim>
std::unique_ptr<AntiLocking<dim>> AntiLocking<dim>::create(const Dictionary& schemes) {
    return selectByWord<AntiLockingRegistry<dim>>(schemes, "antiLocking", "none");
}

template class AntiLocking<2>;
template class AntiLocking<3>;

} // namespace mpm
