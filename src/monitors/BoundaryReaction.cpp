// SPDX-License-Identifier: GPL-3.0-or-later
#include "monitors/FunctionObject.hpp"

namespace mpm {

/// `type: boundaryReaction`: the force the material exerts on each grid face [N] (per metre
/// in 2D), from the momentum the face's boundary condition removed in the step:
/// F_face = Σ_i m_i (v_i⁻ - v_i⁺)/Δt over the face's nodes, one column per face and axis.
template <int dim> class BoundaryReaction final : public FunctionObject<dim> {
public:
    BoundaryReaction(const Dictionary& dict, const std::string& name)
        : FunctionObject<dim>(dict, name) {
        for (int f = 0; f < 2 * dim; ++f)
            faceNames_.push_back(Grid<dim>::faceName(f));
    }
    std::string needsStep() const override {
        return "needs the time step's grid update (the momentum the faces removed)";
    }

protected:
    std::vector<std::string> columns(const State<dim>&) const override {
        std::vector<std::string> c;
        static const char* axes = "xyz";
        for (const auto& f : faceNames_)
            for (int d = 0; d < dim; ++d)
                c.push_back(f + "_F" + axes[d]);
        return c;
    }
    std::vector<double> values(const State<dim>& s) const override {
        std::vector<double> v;
        for (int f = 0; f < 2 * dim; ++f)
            for (int d = 0; d < dim; ++d)
                v.push_back(s.reactions[f][d]);
        return v;
    }

private:
    std::vector<std::string> faceNames_;
};

MPM_REGISTER_DIMS(FunctionObjectRegistry, BoundaryReaction, "boundaryReaction");
MPM_SCHEMA("functionObjects", "boundaryReaction",
           {"the force of the material on each grid face [N] (N/m in 2D)",
            {},
            "{type: boundaryReaction}"});

} // namespace mpm
