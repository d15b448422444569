// SPDX-License-Identifier: GPL-3.0-or-later
#include "monitors/FunctionObject.hpp"

#include <algorithm>

namespace mpm {

/// `type: contactGap`: the smallest signed distance ξ of any material point to any coupled
/// rigid body at the end of each step [m] (negative: a point is inside a body), the smallest
/// since the start of the run, the number of points in contact, and the smallest ξ of the step
/// before the coupling projected points out to ξ_min (Coupling::enforceGap). With the barrier
/// the first stays ≥ ξ_min > 0 by construction (the projection is a safety net) and the last
/// shows whether the barrier force alone kept the points out; with the linear spring nothing
/// is projected, both are equal and show how far points sink in. Sampled every step.
template <int dim> class ContactGap final : public FunctionObject<dim> {
public:
    ContactGap(const Dictionary& dict, const std::string& name) : FunctionObject<dim>(dict, name) {}
    std::string needsStep() const override {
        return "needs the time step's contact search (the gaps and contacts of the step)";
    }

protected:
    void initialise(const State<dim>& s, const Time&) override {
        if (s.bodies.empty())
            this->dict().error("type", "contactGap needs rigid bodies (constant/rigidBodies)");
    }
    void sample(const State<dim>& s, const Time&) override {
        smallest_ = std::min(smallest_, s.minimumGap);
    }
    std::vector<std::string> columns(const State<dim>&) const override {
        return {"minimumGap", "smallestSoFar", "contacts", "minimumGapBeforeProjection"};
    }
    std::vector<double> values(const State<dim>& s) const override {
        return {s.minimumGap, smallest_, static_cast<double>(s.contacts),
                s.minimumGapBeforeProjection};
    }

private:
    double smallest_ = 1e300;
};

MPM_REGISTER_DIMS(FunctionObjectRegistry, ContactGap, "contactGap");
MPM_SCHEMA("functionObjects", "contactGap",
           {"the smallest point-body gap and the number of point-body contacts",
            {},
            "{type: contactGap}"});

} // namespace mpm
