// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Dictionary.hpp"
#include "case/Registry.hpp"
#include "particles/BlockSort.hpp"
#include "transfers/FieldViews.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace mpm {

/// What G2P saw: the largest particle speed, the largest speed a particle moved with (the grid
/// velocity, [000 Eq. 16]: its displacement over Δt) and that particle (the first of equals; -1
/// if none moved), the kinetic energy, and the first particle whose velocity is not finite (-1 if
/// none).
struct GatherStats {
    double maxSpeed = 0;
    double maxMoveSpeed = 0;
    Index fastestMoving = -1;
    double kineticEnergy = 0;
    Index firstNonFinite = -1;
};

/// The selected kernel as a backend sees it (system/mpmSchemes `kernel`): its name, stencil
/// width W (nodes per axis), GIMP's half-width l_p/h (0 for the others), APIC's inertia factor
/// D_p/h² (0 where the kernel has no constant D_p), and the 1D weights: eval(ξ, w, w') fills the
/// W weights w and derivatives w' [per cell] of a coordinate ξ in cell units and returns the
/// index of the first stencil node.
struct KernelFunction {
    std::string name;
    int width = 0;
    double halfWidth = 0.0;
    double inertiaFactor = 0.0;
    std::function<int(double, double*, double*)> eval;
};

/// The velocity scheme of the transfers (system/mpmSchemes `transfer`): APIC's affine terms, or
/// the FLIP/PIC blend with ratio η (PIC: η = 0).
struct TransferOptions {
    bool affine = false;
    double ratio = 0.0;
};

/// A compute backend's particle ↔ grid operations for one kernel and one velocity scheme,
/// chosen once at set-up (system/mpmSchemes `backend`, `kernel`, `transfer`): the transfers,
/// each one phase over all particles, and the grid update. They take views of the fields
/// (PointFields, NodeFields: pointers and sizes), not the containers; the non-virtual overloads
/// taking Particles and Grid make the views. Backends (the family `backends`): `cpu`, the
/// optimised loops (Transfer.cpp), and `reference`, the naive loops written straight from the
/// equations (ReferenceTransfer.cpp), against which every transfer test runs the other; a new
/// backend implements this interface in its own folder and registers in BackendRegistry
/// (docs/architecture.md, "A compute backend").
template <int dim> class Transfer {
public:
    virtual ~Transfer() = default;

    /// Kernel weights and gradients of every particle at its present position, for all
    /// transfers of the step (the fields must outlive them, and x must not change before the
    /// first of them). A backend may evaluate them lazily, where first needed.
    virtual void computeWeights(const PointFields<dim>& p, const NodeFields<dim>& g) = 0;

    /// P2G of mass and momentum [000 Eq. 13] (APIC adds the affine term m_p C_p (x_i - x_p))
    /// into the grid's active blocks, which must hold every stencil (Grid::activate); the sums
    /// are added to the node fields.
    /// With `withStress` the internal force f_i = -Σ V_p σ_p ∇w_ip is scattered in the same
    /// pass (USL); otherwise it is left for scatterForce (USF).
    virtual void scatter(const PointFields<dim>& p, const NodeFields<dim>& g,
                         const BlockSort<dim>& s, bool withStress) = 0;
    /// P2G of the internal force alone (USF's second scatter).
    virtual void scatterForce(const PointFields<dim>& p, const NodeFields<dim>& g,
                              const BlockSort<dim>& s) = 0;

    /// Add external point forces f_k at particles ids[k] to the grid force: f_i += Σ w_ip f_p
    /// (the coupling forces [000 Eq. 19–20]); serial, in list order (deterministic).
    virtual void scatterPointForces(const std::vector<Index>& ids, const std::vector<Vec<dim>>& f,
                                    const NodeFields<dim>& g) const = 0;

    /// out_i += Σ_p w_ip q_p for a particle scalar q with this step's weights; `out` (a node
    /// field) must be zero on the active blocks (Grid::activeBlocks) on entry. Race-free and
    /// deterministic.
    virtual void scatterScalar(const double* q, double* out, const BlockSort<dim>& s) const = 0;
    /// out_p = Σ_i w_ip q_i for a nodal scalar q with this step's weights (out: one per point).
    virtual void gatherScalar(const double* q, double* out) const = 0;

    /// L_p = Σ_i v_i ⊗ ∇w_ip from the P2G velocity g.vOld (USF) [002 Eq. 75].
    virtual void velocityGradient(const PointFields<dim>& p, const NodeFields<dim>& g) = 0;

    /// G2P: velocity by the FLIP/PIC blend [000 Eq. 15] or APIC [000 Eq. 17], position
    /// [000 Eq. 16], and (with `withGradient`, USL) L_p from the updated velocity. May use the
    /// grid's scratch lines, which it overwrites.
    virtual GatherStats gather(const PointFields<dim>& p, const NodeFields<dim>& g, double dt,
                               bool withGradient) = 0;

    /// The P2G velocity v_old,i = (m v)_i / m_i (0 where m_i = 0) on the nodes of `blocks`.
    virtual void velocityFromMomentum(const NodeFields<dim>& g,
                                      const std::vector<Index>& blocks) const = 0;
    /// The grid update [000 Eq. 14] on the nodes of `blocks` with mass: v_old = (m v)/m,
    /// f = f_int + m g minus the local non-viscous damping α |f| sign(v_old) per component,
    /// v = v_old + Δt f / m. Nodes without mass keep their values.
    virtual void updateVelocity(const NodeFields<dim>& g, const std::vector<Index>& blocks,
                                const Vec<dim>& gravity, double damping, double dt) const = 0;

    /// Bytes of kernel data kept per particle between computeWeights and the last transfer of
    /// the step (the stencil: first node, weights, gradients; APIC adds the offset).
    virtual std::size_t stencilBytes() const = 0;

    // The same on the containers (the points of the first three are only read).
    void computeWeights(const Particles<dim>& p, Grid<dim>& g) {
        computeWeights(readOnlyFieldsOf(p), fieldsOf(g));
    }
    void scatter(const Particles<dim>& p, Grid<dim>& g, const BlockSort<dim>& s, bool withStress) {
        scatter(readOnlyFieldsOf(p), fieldsOf(g), s, withStress);
    }
    void scatterForce(const Particles<dim>& p, Grid<dim>& g, const BlockSort<dim>& s) {
        scatterForce(readOnlyFieldsOf(p), fieldsOf(g), s);
    }
    void scatterPointForces(const std::vector<Index>& ids, const std::vector<Vec<dim>>& f,
                            Grid<dim>& g) const {
        scatterPointForces(ids, f, fieldsOf(g));
    }
    void scatterScalar(const std::vector<double>& q, NodeArray<double>& out,
                       const BlockSort<dim>& s) const {
        scatterScalar(q.data(), out.data(), s);
    }
    void gatherScalar(const NodeArray<double>& q, std::vector<double>& out) const {
        out.resize(weightedPoints());
        gatherScalar(q.data(), out.data());
    }
    void velocityGradient(Particles<dim>& p, Grid<dim>& g) {
        velocityGradient(fieldsOf(p), fieldsOf(g));
    }
    GatherStats gather(Particles<dim>& p, Grid<dim>& g, double dt, bool withGradient) {
        return gather(fieldsOf(p), fieldsOf(g), dt, withGradient);
    }

    /// The number of points of the last computeWeights.
    Index weightedPoints() const { return weighted_; }

    /// Build the backend and transfer selected in system/mpmSchemes (`backend`, default cpu;
    /// `kernel`; `transfer`); `particleHalfWidth` is GIMP's l_p / h.
    static std::unique_ptr<Transfer> create(const Dictionary& schemes, double particleHalfWidth);

protected:
    Index weighted_ = 0; ///< set by computeWeights
};

/// A kernel (system/mpmSchemes `kernel`, the family `kernels`, registered with
/// MPM_REGISTER_KERNEL in Transfer.cpp): its description for any backend (function()), and the
/// cpu backend's loops instantiated for its type (makeCpu: the kernel type is known only where
/// it registers).
template <int dim> struct KernelChoice {
    virtual ~KernelChoice() = default;
    virtual KernelFunction function() const = 0;
    virtual std::unique_ptr<Transfer<dim>> makeCpu(const TransferOptions& options) const = 0;
};

/// A compute backend (system/mpmSchemes `backend`, the family `backends`): it builds the
/// transfers of a kernel and a velocity scheme. Registered with MPM_REGISTER(BackendRegistry<dim>,
/// …) for each dimension it serves.
template <int dim> struct Backend {
    virtual ~Backend() = default;
    virtual std::unique_ptr<Transfer<dim>> make(const KernelChoice<dim>& kernel,
                                                const TransferOptions& options) const = 0;
};
template <int dim> using BackendRegistry = Registry<Backend<dim>>;

} // namespace mpm
