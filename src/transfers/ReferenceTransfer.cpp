// SPDX-License-Identifier: GPL-3.0-or-later
#include "case/Selection.hpp"
#include "transfers/Transfer.hpp"

#include <algorithm>
#include <cmath>

namespace mpm {

namespace {

/// The `reference` backend: the transfers written straight from the equations, one point at a
/// time in index order, each stencil node visited as a tensor product of the 1D weights, no
/// threads, no SIMD, no stored stencils (the positions x^n are kept instead). Slow; its use is
/// to check the `cpu` backend (and any other) term by term: every transfer test runs against
/// both (tests/unit/transfers/TransferTest.cpp), and a case runs with either
/// (tests/run/backends.sh).
template <int dim> class ReferenceTransfer final : public Transfer<dim> {
public:
    ReferenceTransfer(KernelFunction kernel, const TransferOptions& options)
        : k_(std::move(kernel)), options_(options) {}

    void computeWeights(const PointFields<dim>& p, const NodeFields<dim>& g) override {
        grid_ = g;
        this->weighted_ = p.size();
        x0_.assign(p.x, p.x + p.size());
    }

    void scatter(const PointFields<dim>& p, const NodeFields<dim>& g, const BlockSort<dim>&,
                 bool withStress) override {
        for (Index i = 0; i < p.size(); ++i) {
            // [000 Eq. 13]: m_i = Σ w m_p, (m v)_i = Σ w m_p (v_p + C_p (x_i − x_p)) (APIC).
            const double m = p.mass[i];
            forStencil(i, [&](Index node, double w, const Vec<dim>& grad, const Vec<dim>& dx) {
                g.mass[node] += w * m;
                Vec<dim> v = p.v[i];
                if (options_.affine) v += p.C[i] * dx;
                g.momentum[node] += w * m * v;
                if (withStress) g.force[node] += internalForce(p, i, grad);
            });
        }
    }

    void scatterForce(const PointFields<dim>& p, const NodeFields<dim>& g,
                      const BlockSort<dim>&) override {
        for (Index i = 0; i < p.size(); ++i)
            forStencil(i, [&](Index node, double, const Vec<dim>& grad, const Vec<dim>&) {
                g.force[node] += internalForce(p, i, grad);
            });
    }

    void scatterPointForces(const std::vector<Index>& ids, const std::vector<Vec<dim>>& f,
                            const NodeFields<dim>& g) const override {
        for (std::size_t k = 0; k < ids.size(); ++k)
            forStencil(ids[k], [&](Index node, double w, const Vec<dim>&, const Vec<dim>&) {
                g.force[node] += w * f[k];
            });
    }

    void scatterScalar(const double* q, double* out, const BlockSort<dim>&) const override {
        for (Index i = 0; i < this->weighted_; ++i)
            forStencil(i, [&](Index node, double w, const Vec<dim>&, const Vec<dim>&) {
                out[node] += w * q[i];
            });
    }

    void gatherScalar(const double* q, double* out) const override {
        for (Index i = 0; i < this->weighted_; ++i) {
            out[i] = 0.0;
            forStencil(i, [&](Index node, double w, const Vec<dim>&, const Vec<dim>&) {
                out[i] += w * q[node];
            });
        }
    }

    void velocityGradient(const PointFields<dim>& p, const NodeFields<dim>& g) override {
        for (Index i = 0; i < p.size(); ++i) {
            p.L[i].setZero();
            forStencil(i, [&](Index node, double, const Vec<dim>& grad, const Vec<dim>&) {
                p.L[i] += g.vOld[node] * grad.transpose();
            });
        }
    }

    GatherStats gather(const PointFields<dim>& p, const NodeFields<dim>& g, double dt,
                       bool withGradient) override {
        GatherStats st;
        double move2 = 0.0;
        for (Index i = 0; i < p.size(); ++i) {
            // v_PIC = Σ w v_i, Δv = Σ w (v_i − v_old,i), B = Σ w v_i (x_i − x_p)ᵀ, L = Σ v_i ⊗ ∇w.
            Vec<dim> vPic = Vec<dim>::Zero(), dv = Vec<dim>::Zero();
            Mat<dim> B = Mat<dim>::Zero(), L = Mat<dim>::Zero();
            forStencil(i, [&](Index node, double w, const Vec<dim>& grad, const Vec<dim>& dx) {
                vPic += w * g.v[node];
                dv += w * (g.v[node] - g.vOld[node]);
                B += w * g.v[node] * dx.transpose();
                L += g.v[node] * grad.transpose();
            });
            Vec<dim> v = vPic; // PIC, and APIC's velocity [000 Eq. 17]
            if (options_.affine) {
                // C = B D⁻¹ with D = D_p/h² h² [000 Eq. 17].
                p.C[i] = B / (k_.inertiaFactor * grid_.h() * grid_.h());
            } else if (options_.ratio > 0.0) {
                // [000 Eq. 15]: v = η (v_p + Δv) + (1 − η) v_PIC.
                v = options_.ratio * (p.v[i] + dv) + (1.0 - options_.ratio) * vPic;
            }
            p.v[i] = v;
            if (withGradient) p.L[i] = L;
            p.x[i] += dt * vPic; // [000 Eq. 16]
            const double m2 = vPic.squaredNorm(), v2 = v.squaredNorm();
            if (m2 > move2) {
                move2 = m2;
                st.fastestMoving = i;
            }
            if (st.firstNonFinite < 0 && !(std::isfinite(v2) && std::isfinite(p.x[i].sum())))
                st.firstNonFinite = i;
            st.maxSpeed = std::max(st.maxSpeed, std::sqrt(v2));
            st.kineticEnergy += 0.5 * p.mass[i] * v2;
        }
        st.maxMoveSpeed = std::sqrt(move2);
        return st;
    }

    void velocityFromMomentum(const NodeFields<dim>& g,
                              const std::vector<Index>& blocks) const override {
        forNodes(g, blocks, [&](Index n) {
            g.vOld[n] = g.mass[n] > 0 ? Vec<dim>(g.momentum[n] / g.mass[n]) : Vec<dim>::Zero();
        });
    }

    void updateVelocity(const NodeFields<dim>& g, const std::vector<Index>& blocks,
                        const Vec<dim>& gravity, double damping, double dt) const override {
        forNodes(g, blocks, [&](Index n) {
            const double m = g.mass[n];
            if (!(m > 0)) return;
            const Vec<dim> v0 = g.momentum[n] / m;
            Vec<dim> f = g.force[n] + m * gravity; // [000 Eq. 14]
            for (int a = 0; a < dim; ++a)          // f ← f − α |f| sign(v0), per component
                f[a] -= damping * std::fabs(f[a]) * ((v0[a] > 0) - (v0[a] < 0));
            g.vOld[n] = v0;
            g.v[n] = v0 + (dt / m) * f;
        });
    }

    std::size_t stencilBytes() const override { return sizeof(Vec<dim>); }

private:
    /// f_i contribution −V_p σ_p ∇w_ip of point i [000 Eq. 13].
    static Vec<dim> internalForce(const PointFields<dim>& p, Index i, const Vec<dim>& grad) {
        return -p.volume[i] * (p.stress[i].template topLeftCorner<dim, dim>() * grad);
    }

    /// Visit the stencil of point i at its x^n: fn(node, w_ip, ∇w_ip [1/m], x_i − x_p [m]), with
    /// w_ip = Π_d w(ξ_d) and ∂_e w_ip = w'(ξ_e)/h Π_{d≠e} w(ξ_d), ξ = (x_p − origin)/h.
    template <class Fn> void forStencil(Index i, Fn&& fn) const {
        constexpr int MaxWidth = 8;
        const int W = k_.width;
        double w[dim][MaxWidth], dw[dim][MaxWidth];
        int base[dim];
        const Vec<dim> xh = (x0_[i] - grid_.origin()) / grid_.h();
        for (int d = 0; d < dim; ++d)
            base[d] = k_.eval(xh[d], w[d], dw[d]);
        int count = 1;
        for (int d = 0; d < dim; ++d)
            count *= W;
        for (int s = 0; s < count; ++s) {
            int a[dim];
            for (int d = 0, r = s; d < dim; ++d, r /= W)
                a[d] = r % W;
            double wip = 1.0;
            Vec<dim> grad = Vec<dim>::Constant(1.0 / grid_.h());
            Vec<dim> dx;
            Index node = 0;
            for (int d = 0; d < dim; ++d) {
                wip *= w[d][a[d]];
                for (int e = 0; e < dim; ++e)
                    grad[e] *= e == d ? dw[d][a[d]] : w[d][a[d]];
                node += grid_.axisOffset(d, base[d] + a[d]);
                dx[d] = grid_.origin()[d] + (base[d] + a[d]) * grid_.h() - x0_[i][d];
            }
            fn(node, wip, grad, dx);
        }
    }

    /// Every node of the given blocks within the grid's nodes (not the padding of the last
    /// blocks), one at a time.
    template <class Fn>
    static void forNodes(const NodeFields<dim>& g, const std::vector<Index>& blocks, Fn&& fn) {
        const GridLayout<dim>& layout = *g.layout;
        for (Index b : blocks)
            for (Index n = b * layout.NodesPerBlock; n < (b + 1) * layout.NodesPerBlock; ++n) {
                const IVec<dim> c = layout.nodeCoord(n);
                bool inside = true;
                for (int d = 0; d < dim; ++d)
                    inside = inside && c[d] < layout.nodes()[d];
                if (inside) fn(n);
            }
    }

    KernelFunction k_;
    TransferOptions options_;
    NodeFields<dim> grid_;     ///< the layout of computeWeights
    std::vector<Vec<dim>> x0_; ///< the points' x^n at computeWeights
};

template <int dim> struct ReferenceBackend final : Backend<dim> {
    explicit ReferenceBackend(const Dictionary&) {}
    std::unique_ptr<Transfer<dim>> make(const KernelChoice<dim>& kernel,
                                        const TransferOptions& options) const override {
        return std::make_unique<ReferenceTransfer<dim>>(kernel.function(), options);
    }
};

} // namespace

MPM_REGISTER_DIMS(BackendRegistry, ReferenceBackend, "reference");
MPM_SCHEMA("backends", "reference",
           {"the transfers written straight from the equations, one point at a time, no threads "
            "(for checking other backends; block2D: P2G 1.4x, G2P 6x the cpu backend's time on "
            "one thread)",
            {},
            "backend: reference"});

} // namespace mpm
