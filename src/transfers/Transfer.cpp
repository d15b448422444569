// SPDX-License-Identifier: GPL-3.0-or-later
#include "transfers/Transfer.hpp"

#include "kernels/Kernels.hpp"

#include <array>
#include <cmath>

namespace mpm {

namespace {

constexpr int ipow(int b, int e) { return e == 0 ? 1 : b * ipow(b, e - 1); }

/// Transfers for kernel K; `Affine` selects APIC, otherwise the FLIP/PIC blend with ratio η.
template <int dim, class K, bool Affine> class TransferImpl final : public Transfer<dim> {
    static constexpr int W = K::Width;
    static constexpr int S = ipow(W, dim);

    /// Kernel data of one particle: first stencil node, 1D weights and derivatives per axis,
    /// and the particle's offset from the first node in cell units.
    struct Stencil {
        Index node0;
        double w[dim][W];
        double dw[dim][W];
        Vec<dim> fx;
    };

public:
    TransferImpl(K kernel, double ratio) : kernel_(kernel), ratio_(ratio) {}

    void computeWeights(const Particles<dim>& p, const Grid<dim>& g) override {
        if (offsets_.empty()) buildOffsets(g);
        const Index n = static_cast<Index>(p.size());
        st_.resize(n);
        const Vec<dim> origin = g.origin();
        const double invH = g.invH();
#pragma omp parallel for schedule(static)
        for (Index i = 0; i < n; ++i) {
            Stencil& s = st_[i];
            const Vec<dim> xh = (p.x[i] - origin) * invH;
            Index node0 = 0;
            for (int d = 0; d < dim; ++d) {
                const int base = kernel_.eval(xh[d], s.w[d], s.dw[d]);
                s.fx[d] = xh[d] - base;
                node0 += static_cast<Index>(base) * g.stride(d);
            }
            s.node0 = node0;
        }
    }

    void scatter(const Particles<dim>& p, Grid<dim>& g, const BlockSort<dim>& sort,
                 bool withStress) override {
        if (withStress)
            scatterImpl<true, true>(p, g, sort);
        else
            scatterImpl<true, false>(p, g, sort);
    }

    void scatterForce(const Particles<dim>& p, Grid<dim>& g, const BlockSort<dim>& sort) override {
        scatterImpl<false, true>(p, g, sort);
    }

    void velocityGradient(Particles<dim>& p, const Grid<dim>& g) override {
        const Index n = static_cast<Index>(p.size());
        const double invH = g.invH();
#pragma omp parallel for schedule(static)
        for (Index i = 0; i < n; ++i) {
            const Stencil& s = st_[i];
            Mat<dim> L = Mat<dim>::Zero();
            for (int k = 0; k < S; ++k) {
                double wgt;
                Vec<dim> grad;
                weightAndGradient(s, k, wgt, grad);
                L.noalias() += g.vOld[s.node0 + offsets_[k]] * grad.transpose();
            }
            p.L[i] = L * invH;
        }
    }

    GatherStats gather(Particles<dim>& p, const Grid<dim>& g, double dt,
                       bool withGradient) override {
        const bool flip = !Affine && ratio_ > 0.0;
        if (withGradient)
            return flip ? gatherImpl<true, true>(p, g, dt) : gatherImpl<true, false>(p, g, dt);
        return flip ? gatherImpl<false, true>(p, g, dt) : gatherImpl<false, false>(p, g, dt);
    }

private:
    void buildOffsets(const Grid<dim>& g) {
        offsets_.resize(S);
        for (int k = 0; k < S; ++k) {
            int r = k;
            Index off = 0;
            for (int d = 0; d < dim; ++d) {
                ko_[k][d] = r % W;
                r /= W;
                off += ko_[k][d] * g.stride(d);
            }
            offsets_[k] = off;
        }
    }

    /// Weight w_ip and gradient in cell units (∇w · h) of stencil point k.
    inline void weightAndGradient(const Stencil& s, int k, double& wgt, Vec<dim>& grad) const {
        if constexpr (dim == 2) {
            const int a = ko_[k][0], b = ko_[k][1];
            wgt = s.w[0][a] * s.w[1][b];
            grad = Vec<dim>(s.dw[0][a] * s.w[1][b], s.w[0][a] * s.dw[1][b]);
        } else {
            const int a = ko_[k][0], b = ko_[k][1], c = ko_[k][2];
            const double wyz = s.w[1][b] * s.w[2][c];
            wgt = s.w[0][a] * wyz;
            grad = Vec<dim>(s.dw[0][a] * wyz, s.w[0][a] * s.dw[1][b] * s.w[2][c],
                            s.w[0][a] * s.w[1][b] * s.dw[2][c]);
        }
    }

    inline Vec<dim> nodeOffset(const Stencil& s, int k) const {
        Vec<dim> o;
        for (int d = 0; d < dim; ++d) o[d] = ko_[k][d] - s.fx[d];
        return o;
    }

    template <bool Momentum, bool Stress>
    void scatterImpl(const Particles<dim>& p, Grid<dim>& g, const BlockSort<dim>& sort) {
        const double h = g.h();
        const double invH = g.invH();
        const auto& order = sort.order();
        for (int colour = 0; colour < BlockSort<dim>::NumColours; ++colour) {
            const auto& blocks = sort.blocksOfColour(colour);
            const Index nb = static_cast<Index>(blocks.size());
#pragma omp parallel for schedule(dynamic, 1)
            for (Index bi = 0; bi < nb; ++bi) {
                const Index b = blocks[bi];
                for (Index j = sort.start(b); j < sort.start(b + 1); ++j) {
                    const Index i = order[j];
                    const Stencil& s = st_[i];
                    const double m = p.mass[i];
                    const Vec<dim> mv = m * p.v[i];
                    Mat<dim> mC = Mat<dim>::Zero();
                    if constexpr (Affine) mC = (m * h) * p.C[i];
                    Mat<dim> stressTerm = Mat<dim>::Zero();
                    if constexpr (Stress)
                        stressTerm = (-p.volume[i] * invH) *
                                     p.stress[i].template topLeftCorner<dim, dim>();
                    for (int k = 0; k < S; ++k) {
                        double wgt;
                        Vec<dim> grad;
                        weightAndGradient(s, k, wgt, grad);
                        const Index node = s.node0 + offsets_[k];
                        if constexpr (Momentum) {
                            g.mass[node] += wgt * m;
                            if constexpr (Affine)
                                g.momentum[node] += wgt * (mv + mC * nodeOffset(s, k));
                            else
                                g.momentum[node] += wgt * mv;
                        }
                        if constexpr (Stress) g.force[node] += stressTerm * grad;
                    }
                }
            }
        }
    }

    template <bool Grad, bool Flip>
    GatherStats gatherImpl(Particles<dim>& p, const Grid<dim>& g, double dt) {
        const Index n = static_cast<Index>(p.size());
        const double invH = g.invH();
        const double eta = ratio_;
        double vmax2 = 0.0, ke = 0.0;
        Index bad = n;
#pragma omp parallel for schedule(static) reduction(max : vmax2) reduction(+ : ke) \
    reduction(min : bad)
        for (Index i = 0; i < n; ++i) {
            const Stencil& s = st_[i];
            Vec<dim> vPic = Vec<dim>::Zero();
            Vec<dim> dv = Vec<dim>::Zero();
            Mat<dim> B = Mat<dim>::Zero();
            Mat<dim> L = Mat<dim>::Zero();
            for (int k = 0; k < S; ++k) {
                double wgt;
                Vec<dim> grad;
                weightAndGradient(s, k, wgt, grad);
                const Index node = s.node0 + offsets_[k];
                const Vec<dim>& vi = g.v[node];
                vPic += wgt * vi;
                if constexpr (Flip) dv += wgt * (vi - g.vOld[node]);
                if constexpr (Affine) B.noalias() += (wgt * vi) * nodeOffset(s, k).transpose();
                if constexpr (Grad) L.noalias() += vi * grad.transpose();
            }
            if constexpr (Affine) {
                p.v[i] = vPic;
                p.C[i] = B * (invH / K::InertiaFactor);
            } else if constexpr (Flip) {
                p.v[i] = eta * (p.v[i] + dv) + (1.0 - eta) * vPic;
            } else {
                p.v[i] = vPic;
            }
            if constexpr (Grad) p.L[i] = L * invH;
            p.x[i] += dt * vPic;
            const double v2 = p.v[i].squaredNorm();
            if (!std::isfinite(v2) || !std::isfinite(p.x[i].sum())) bad = std::min(bad, i);
            vmax2 = std::max(vmax2, v2);
            ke += 0.5 * p.mass[i] * v2;
        }
        GatherStats st;
        st.maxSpeed = std::sqrt(vmax2);
        st.kineticEnergy = ke;
        st.firstNonFinite = bad < n ? bad : -1;
        return st;
    }

    K kernel_;
    double ratio_;
    std::vector<Stencil> st_;
    std::vector<Index> offsets_;
    int ko_[S][dim] = {};
};

/// APIC needs a kernel with constant inertia D_p (quadratic or cubic B-spline).
template <class K> constexpr bool hasInertia() {
    return std::is_same_v<K, QuadraticBSplineKernel> || std::is_same_v<K, CubicBSplineKernel>;
}

template <int dim, class K>
std::unique_ptr<Transfer<dim>> makeFor(K kernel, const std::string& scheme, double ratio,
                                       const Dictionary& schemes) {
    if (scheme == "apic") {
        if constexpr (hasInertia<K>())
            return std::make_unique<TransferImpl<dim, K, true>>(kernel, 0.0);
        else
            schemes.error("transfer", std::string("apic needs kernel quadraticBSpline or "
                                                  "cubicBSpline (constant D_p), not ") +
                                          K::Name);
    }
    return std::make_unique<TransferImpl<dim, K, false>>(kernel, ratio);
}

} // namespace

template <int dim>
std::unique_ptr<Transfer<dim>> Transfer<dim>::create(const Dictionary& schemes,
                                                     double particleHalfWidth) {
    const std::string kernel = schemes.getWord("kernel", kernelNames());
    std::string scheme;
    double ratio = 0.0;
    const std::vector<std::string> schemesValid{"pic", "flip", "apic"};
    if (schemes.isDict("transfer")) {
        const Dictionary t = schemes.subDict("transfer");
        scheme = t.getWord("type", schemesValid);
        if (scheme == "flip") ratio = t.getScalarOr("ratio", 0.995, Bounds::closed(0.0, 1.0));
        t.checkUnknownKeys();
    } else {
        scheme = schemes.getWord("transfer", schemesValid);
        if (scheme == "flip") ratio = 0.995;
    }
    if (kernel == LinearKernel::Name) return makeFor<dim>(LinearKernel{}, scheme, ratio, schemes);
    if (kernel == GimpKernel::Name) {
        GimpKernel k;
        k.l = std::min(particleHalfWidth, 0.49);
        return makeFor<dim>(k, scheme, ratio, schemes);
    }
    if (kernel == QuadraticBSplineKernel::Name)
        return makeFor<dim>(QuadraticBSplineKernel{}, scheme, ratio, schemes);
    return makeFor<dim>(CubicBSplineKernel{}, scheme, ratio, schemes);
}

template class Transfer<2>;
template class Transfer<3>;

} // namespace mpm
