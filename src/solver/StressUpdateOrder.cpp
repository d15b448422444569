// SPDX-License-Identifier: GPL-3.0-or-later
#include "solver/StressUpdateOrder.hpp"

#include "case/Selection.hpp"

namespace mpm {

MPM_FAMILY_INFO("stressUpdateOrders", {"stressUpdate in system/mpmSchemes (a word; default USL)",
                                       "3. system/mpmSchemes",
                                       {}});
MPM_FAMILY(StressUpdateOrderRegistry, 0, "stressUpdateOrders");

namespace {

class UpdateStressLast final : public StressUpdateOrder {
public:
    explicit UpdateStressLast(const Dictionary&) {}
    bool forceWithMomentum() const override { return true; }
    bool gradientInGridToParticle() const override { return true; }
    void afterGridToParticle(StressPhases& s, double dt) const override { s.updateStress(dt); }
};

class UpdateStressFirst final : public StressUpdateOrder {
public:
    explicit UpdateStressFirst(const Dictionary&) {}
    bool forceWithMomentum() const override { return false; }
    bool gradientInGridToParticle() const override { return false; }
    bool gradientBeforeUpdate() const override { return true; }
    void afterParticleToGrid(StressPhases& s, double dt) const override {
        s.gridVelocityFromMomentum();
        s.velocityGradient();
        s.updateStress(dt);
        s.scatterInternalForce();
    }
};

class ModifiedUpdateStressLast final : public StressUpdateOrder {
public:
    explicit ModifiedUpdateStressLast(const Dictionary&) {}
    bool forceWithMomentum() const override { return true; }
    bool gradientInGridToParticle() const override { return false; }
    void afterGridToParticle(StressPhases& s, double dt) const override {
        s.remapMomentum();
        s.gridVelocityFromMomentum();
        s.velocityGradient();
        s.updateStress(dt);
    }
};

} // namespace

MPM_REGISTER(StressUpdateOrderRegistry, UpdateStressLast, "USL");
MPM_SCHEMA("stressUpdateOrders", "USL",
           {"update stress last: the stress is updated after G2P, L from the updated grid velocity",
            {},
            "stressUpdate: USL"});
MPM_REGISTER(StressUpdateOrderRegistry, UpdateStressFirst, "USF");
MPM_SCHEMA("stressUpdateOrders", "USF",
           {"update stress first: after P2G, before the grid update, L from the P2G velocity",
            {},
            "stressUpdate: USF"});
MPM_REGISTER(StressUpdateOrderRegistry, ModifiedUpdateStressLast, "MUSL");
MPM_SCHEMA("stressUpdateOrders", "MUSL",
           {"modified USL: after G2P, L from a second projection of the updated momenta",
            {},
            "stressUpdate: MUSL"});

std::unique_ptr<StressUpdateOrder> StressUpdateOrder::create(const Dictionary& schemes) {
    return selectByWord<StressUpdateOrderRegistry>(schemes, "stressUpdate", "USL");
}

} // namespace mpm
