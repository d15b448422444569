// SPDX-License-Identifier: GPL-3.0-or-later
#include "solver/StressUpdateOrder.hpp"

namespace mpm {

namespace {

class UpdateStressLast final : public StressUpdateOrder {
public:
    bool forceWithMomentum() const override { return true; }
    bool gradientInGridToParticle() const override { return true; }
    void afterGridToParticle(StressPhases& s, double dt) const override { s.updateStress(dt); }
};

class UpdateStressFirst final : public StressUpdateOrder {
public:
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

std::unique_ptr<StressUpdateOrder> StressUpdateOrder::create(const Dictionary& schemes) {
    const std::string order = schemes.getWordOr("stressUpdate", "USL", {"USF", "USL", "MUSL"});
    if (order == "USF") return std::make_unique<UpdateStressFirst>();
    if (order == "MUSL") return std::make_unique<ModifiedUpdateStressLast>();
    return std::make_unique<UpdateStressLast>();
}

} // namespace mpm
