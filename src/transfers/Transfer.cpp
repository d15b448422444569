// SPDX-License-Identifier: GPL-3.0-or-later
#include "transfers/Transfer.hpp"
#include "case/Selection.hpp"
#include "core/Parallel.hpp"
#include "core/Stream.hpp"

#include "kernels/Kernels.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <type_traits>

namespace mpm {

namespace {

/// Four doubles as one SIMD vector (GCC/Clang vector extension: one AVX register, or two SSE).
using Double4 = double __attribute__((vector_size(32)));

/// Lanes 0–3 and 4–7 of a node line (memcpy: no aliasing of double by the vector type; it
/// compiles to one aligned vector move).
inline Double4 loadLow(const NodeLine& q) {
    Double4 x;
    std::memcpy(&x, q.v, sizeof x);
    return x;
}
inline Double4 loadHigh(const NodeLine& q) {
    Double4 x;
    std::memcpy(&x, q.v + 4, sizeof x);
    return x;
}

/// A whole node line as one vector (one AVX-512 register, or two AVX ones).
using Double8 = double __attribute__((vector_size(64)));
inline Double8 load(const NodeLine& q) {
    Double8 x;
    std::memcpy(&x, q.v, sizeof x);
    return x;
}
inline void store(NodeLine& q, const Double8& x) {
    std::memcpy(q.v, &x, sizeof x);
}
/// [lo, hi] as one line vector.
inline Double8 join(const Double4& lo, const Double4& hi) {
    return __builtin_shufflevector(lo, hi, 0, 1, 2, 3, 4, 5, 6, 7);
}

/// The grid update of the cpu backend (Transfer::updateVelocity), the node loop of
/// GridLayout::forEachNode.
template <int dim>
void cpuUpdateVelocity(const NodeFields<dim>& g, const std::vector<Index>& blocks,
                       const Vec<dim>& gravity, double damping, double dt) {
    const double alpha = damping;
    const bool damped = alpha > 0; // loop-invariant: hoisted out of the node loop
    g.layout->forEachNode(blocks, [&](Index node) {
        const double m = g.mass[node];
        if (m > 0) {
            // [000 Eq. 14]: (m v)ⁿ⁺¹ = m v + Δt f, with gravity f_ext = m g.
            const Vec<dim> v0 = g.momentum[node] / m;
            Vec<dim> f = g.force[node] + m * gravity;
            // Local non-viscous damping f ← f - α |f| sign(v), per component.
            if (damped)
                for (int a = 0; a < dim; ++a)
                    f[a] -= alpha * std::fabs(f[a]) * ((v0[a] > 0) - (v0[a] < 0));
            g.vOld[node] = v0;
            g.v[node] = v0 + (dt / m) * f;
        }
    });
}

/// v_old = (m v)/m of the cpu backend (Transfer::velocityFromMomentum).
template <int dim>
void cpuVelocityFromMomentum(const NodeFields<dim>& g, const std::vector<Index>& blocks) {
    g.layout->forEachNode(blocks, [&g](Index node) {
        const double m = g.mass[node];
        g.vOld[node] = m > 0 ? Vec<dim>(g.momentum[node] / m) : Vec<dim>::Zero();
    });
}

/// Transfers for kernel K; `Affine` selects APIC, otherwise the FLIP/PIC blend with ratio η.
template <int dim, class K, bool Affine> class TransferImpl final : public Transfer<dim> {
    static constexpr int W = K::Width;

    /// Kernel data of one particle: coordinates of the first stencil node, 1D weights and
    /// derivatives per axis, and (APIC only, whose affine terms need it) the particle's offset
    /// from the first node in cell units: 192 bytes a point in 3D with it, 160 without, 128 in 2D
    /// (whole 32-byte chunks, for streamStore).
    struct StencilWeights {
        int base[dim];
        double w[dim][W];
        double dw[dim][W];
    };
    struct StencilWithOffset : StencilWeights {
        Vec<dim> fx;
    };
    /// Padded to whole 32-byte chunks as a whole (padding the base would push fx past it).
    struct alignas(32) Stencil : std::conditional_t<Affine, StencilWithOffset, StencilWeights> {};
    /// fx_d of an APIC stencil; 0 for the others (the terms that use it are APIC's only).
    static inline double offset([[maybe_unused]] const Stencil& s, [[maybe_unused]] int d) {
        if constexpr (Affine)
            return s.fx[d];
        else
            return 0.0;
    }

public:
    TransferImpl(K kernel, double ratio) : kernel_(kernel), ratio_(ratio) {}

    /// The stencils are evaluated where they are first needed: by the step's first scatter,
    /// each point's in P2G's own pass over it (one pass over the points fewer), or, should
    /// another transfer come first, by ensureWeights.
    void computeWeights(const PointFields<dim>& p, const NodeFields<dim>& g) override {
        grid_ = g;
        points_ = p;
        this->weighted_ = p.size();
        st_.resize(p.size());
        pending_ = true;
    }

    void scatter(const PointFields<dim>& p, const NodeFields<dim>& g, const BlockSort<dim>& sort,
                 bool withStress) override {
        if (withStress)
            scatterImpl<true, true>(p, g, sort);
        else
            scatterImpl<true, false>(p, g, sort);
    }

    void scatterForce(const PointFields<dim>& p, const NodeFields<dim>& g,
                      const BlockSort<dim>& sort) override {
        scatterImpl<false, true>(p, g, sort);
    }

    void scatterPointForces(const std::vector<Index>& ids, const std::vector<Vec<dim>>& f,
                            const NodeFields<dim>& g) const override {
        ensureWeights();
        for (std::size_t k = 0; k < ids.size(); ++k)
            forStencil(st_[ids[k]], [&](Index node, double wgt, const Vec<dim>&) {
                g.force[node] += wgt * f[k];
            });
    }

    void scatterScalar(const double* q, double* out, const BlockSort<dim>& sort) const override {
        ensureWeights();
        const auto& order = sort.order();
        sort.forEachBlockByColour(worthThreads(this->weighted_), [&](Index, auto r) {
            for (Index j = r.begin; j < r.end; ++j) {
                const Index i = order[j];
                forStencil(st_[i], [&](Index node, double wgt, const Vec<dim>&) {
                    out[node] += wgt * q[i];
                });
            }
        });
    }

    void gatherScalar(const double* q, double* out) const override {
        ensureWeights();
        const Index n = static_cast<Index>(st_.size());
#pragma omp parallel for if (worthThreads(n)) schedule(static)
        for (Index i = 0; i < n; ++i) {
            double sum = 0.0;
            forStencil(st_[i],
                       [&](Index node, double wgt, const Vec<dim>&) { sum += wgt * q[node]; });
            out[i] = sum;
        }
    }

    void velocityGradient(const PointFields<dim>& p, const NodeFields<dim>& g) override {
        ensureWeights();
        const Index n = static_cast<Index>(p.size());
        const double invH = g.invH();
#pragma omp parallel for if (worthThreads(n)) schedule(static)
        for (Index i = 0; i < n; ++i) {
            const Stencil& s = st_[i];
            Mat<dim> L = Mat<dim>::Zero();
            forStencil(s, [&](Index node, double, const Vec<dim>& grad) {
                L.noalias() += g.vOld[node] * grad.transpose();
            });
            p.L[i] = L * invH;
        }
    }

    GatherStats gather(const PointFields<dim>& p, const NodeFields<dim>& g, double dt,
                       bool withGradient) override {
        ensureWeights();
        const bool flip = !Affine && ratio_ > 0.0;
        if (withGradient)
            return flip ? gatherImpl<true, true>(p, g, dt) : gatherImpl<true, false>(p, g, dt);
        return flip ? gatherImpl<false, true>(p, g, dt) : gatherImpl<false, false>(p, g, dt);
    }

    void velocityFromMomentum(const NodeFields<dim>& g,
                              const std::vector<Index>& blocks) const override {
        cpuVelocityFromMomentum(g, blocks);
    }

    void updateVelocity(const NodeFields<dim>& g, const std::vector<Index>& blocks,
                        const Vec<dim>& gravity, double damping, double dt) const override {
        cpuUpdateVelocity(g, blocks, gravity, damping, dt);
    }

    std::size_t stencilBytes() const override {
        return sizeof(Stencil);
    }

private:
    /// The stencil of point i at its x^n (computeWeights' points and grid).
    inline void evaluate(Index i) const {
        evaluate(i, st_[i]);
    }
    inline void evaluate(Index i, Stencil& s) const {
        const Vec<dim> xh = (points_.x[i] - grid_.origin()) * grid_.invH();
        for (int d = 0; d < dim; ++d) {
            s.base[d] = kernel_.eval(xh[d], s.w[d], s.dw[d]);
            if constexpr (Affine) s.fx[d] = xh[d] - s.base[d];
        }
    }
    /// Every stencil, if no scatter has evaluated them yet this step.
    void ensureWeights() const {
        if (!pending_) return;
        pending_ = false;
        const Index n = static_cast<Index>(st_.size());
#pragma omp parallel for if (worthThreads(n)) schedule(static)
        for (Index i = 0; i < n; ++i)
            evaluate(i);
    }

    /// Node-index offsets of the stencil along each axis: node (a, b, c) of the stencil is
    /// o[0][a] + o[1][b] + o[2][c] (Grid::axisOffset).
    inline void offsets(const Stencil& s, Index (&o)[dim][W]) const {
        for (int d = 0; d < dim; ++d)
            for (int a = 0; a < W; ++a)
                o[d][a] = grid_.axisOffset(d, s.base[d] + a);
    }

    /// Visit the x-rows of a particle's stencil: row(first node index, weight w_r,
    /// ∂_y w_r, ∂_z w_r, (y_r − y_p)/h, (z_r − z_p)/h) with w_r = w_y w_z (2D: w_y, no z).
    template <class Row>
    static inline void forRows(const Stencil& s, const Index (&o)[dim][W], Row&& row) {
        if constexpr (dim == 2) {
            for (int b = 0; b < W; ++b)
                row(o[1][b], s.w[1][b], s.dw[1][b], 0.0, b - offset(s, 1), 0.0);
        } else {
            for (int c = 0; c < W; ++c) {
                const double wz = s.w[2][c], dz = s.dw[2][c], oz = c - offset(s, 2);
                for (int b = 0; b < W; ++b)
                    row(o[1][b] + o[2][c], s.w[1][b] * wz, s.dw[1][b] * wz, s.w[1][b] * dz,
                        b - offset(s, 1), oz);
            }
        }
    }

    /// G2P of one particle from the node lines [v, 0 | v − v_old, 0] (the second half with
    /// FLIP only), the stencil sums factored per x-row: r0 = Σ_a w_x v_i, r1 = Σ_a a w_x v_i,
    /// r2 = Σ_a w'_x v_i, rd = Σ_a w_x (v_i − v_old,i), each one 4-lane vector (v padded); a
    /// row has weight w_r, derivatives ∂_y w_r, ∂_z w_r and offsets oy, oz.
    template <bool Grad, bool Flip>
    inline void gatherLines(const Stencil& s, const NodeLine* lines, Vec<dim>& vPic, Vec<dim>& dv,
                            Mat<dim>& B, Mat<dim>& L) const {
        Index o[dim][W];
        offsets(s, o);
        const Double4 zero = {0.0, 0.0, 0.0, 0.0};
        Double4 aV = zero, aB0 = zero, aB1 = zero, aB2 = zero, aD = zero;
        Double4 aL0 = zero, aL1 = zero, aL2 = zero;
        auto row = [&](Index first, double wr, double dy, double dz, double oy, double oz) {
            Double4 r0 = zero, r1 = zero, r2 = zero, rd = zero;
            for (int a = 0; a < W; ++a) {
                const NodeLine& q = lines[first + o[0][a]];
                const Double4 v = loadLow(q);
                const double wx = s.w[0][a];
                r0 += wx * v;
                if constexpr (Affine) r1 += (a * wx) * v;
                if constexpr (Grad) r2 += s.dw[0][a] * v;
                if constexpr (Flip) rd += wx * loadHigh(q);
            }
            aV += wr * r0;
            if constexpr (Affine) {
                aB0 += wr * r1;
                aB1 += (wr * oy) * r0;
                if constexpr (dim == 3) aB2 += (wr * oz) * r0;
            }
            if constexpr (Flip) aD += wr * rd;
            if constexpr (Grad) {
                aL0 += wr * r2;
                aL1 += dy * r0;
                if constexpr (dim == 3) aL2 += dz * r0;
            }
        };
        forRows(s, o, row);
        auto vec = [](const Double4& x) {
            Vec<dim> r;
            for (int d = 0; d < dim; ++d)
                r[d] = x[d];
            return r;
        };
        const Double4* aB[3] = {&aB0, &aB1, &aB2};
        const Double4* aL[3] = {&aL0, &aL1, &aL2};
        vPic = vec(aV);
        if constexpr (Flip) dv = vec(aD);
        if constexpr (Affine) {
            // B = Σ w v_i (x_i - x_p)ᵀ/h: column 0 is Σ w v_i (a - fx).
            B.col(0) = vec(aB0) - s.fx[0] * vPic;
            for (int d = 1; d < dim; ++d)
                B.col(d) = vec(*aB[d]);
        }
        if constexpr (Grad)
            for (int d = 0; d < dim; ++d)
                L.col(d) = vec(*aL[d]);
    }

    /// Visit the stencil of one particle as nested loops (x fastest): fn(node, w_ip, ∇w_ip·h).
    template <class Fn> inline void forStencil(const Stencil& s, Fn&& fn) const {
        Index o[dim][W];
        offsets(s, o);
        if constexpr (dim == 2) {
            for (int b = 0; b < W; ++b) {
                const Index row = o[1][b];
                const double wy = s.w[1][b], dy = s.dw[1][b];
                for (int a = 0; a < W; ++a)
                    fn(row + o[0][a], s.w[0][a] * wy, Vec<dim>(s.dw[0][a] * wy, s.w[0][a] * dy));
            }
        } else {
            for (int c = 0; c < W; ++c) {
                const double wz = s.w[2][c], dz = s.dw[2][c];
                for (int b = 0; b < W; ++b) {
                    const Index row = o[1][b] + o[2][c];
                    const double wyz = s.w[1][b] * wz, dyz = s.dw[1][b] * wz;
                    const double wdz = s.w[1][b] * dz;
                    for (int a = 0; a < W; ++a) {
                        const double wx = s.w[0][a];
                        fn(row + o[0][a], wx * wyz, Vec<dim>(s.dw[0][a] * wyz, wx * dyz, wx * wdz));
                    }
                }
            }
        }
    }

    /// P2G of one particle into the node lines: low half [m, momentum, 0], high half
    /// [internal force, 0]. With the stencil factored per x-row (w = w_x w_r,
    /// ∇w·h = (w'_x w_r, w_x ∂_y w_r, w_x ∂_z w_r)), the contribution to node a of a row is
    /// low += w_x(a) R0 + a w_x(a) R1, high += w_x(a) F0 + w'_x(a) F1, with
    /// R0 = w_r [m, m v + m C h (−fx, oy, oz)], R1 = w_r [0, m C h e_x], F0 = S (0, ∂_y w_r,
    /// ∂_z w_r), F1 = w_r S e_x and S = −V σ / h [000 Eq. 13]: on the whole line,
    /// line += w_x(a) [R0, F0] + [a w_x(a), w'_x(a)] [R1, F1], two 8-lane multiply-adds.
    /// A half that is not scattered (no momentum, no stress, no R1 without APIC) gets the
    /// addend w·(−0) = −0 for the weights w_x, a w_x ≥ 0, which leaves every value, signed zeros
    /// included, as it was; w'_x may be negative, but a force half that is not scattered holds
    /// the +0 of the zeroed line, which any signed zero keeps.
    template <bool Momentum, bool Stress>
    inline void scatterOne(const Stencil& s, NodeLine* lines, double m, const Vec<dim>& mv,
                           const Mat<dim>& mC, const Mat<dim>& S) const {
        // Built from registers (brace initialisers), not lane by lane through memory.
        auto at = [](const auto& v, int k) { return k < dim ? v[k] : 0.0; };
        const Double4 zero = {0.0, 0.0, 0.0, 0.0};
        const Double4 none = {-0.0, -0.0, -0.0, -0.0};
        Double4 P = zero, Q[3] = {zero, zero, zero}, T[3] = {zero, zero, zero};
        if constexpr (Momentum) {
            Vec<dim> p0 = mv;
            if constexpr (Affine) p0 -= s.fx[0] * mC.col(0);
            P = Double4{m, at(p0, 0), at(p0, 1), at(p0, 2)};
            if constexpr (Affine)
                for (int d = 0; d < dim; ++d)
                    Q[d] = Double4{0.0, at(mC.col(d), 0), at(mC.col(d), 1), at(mC.col(d), 2)};
        }
        if constexpr (Stress)
            for (int d = 0; d < dim; ++d)
                T[d] = Double4{at(S.col(d), 0), at(S.col(d), 1), at(S.col(d), 2), 0.0};
        Index o[dim][W];
        offsets(s, o);
        // The second multiplier of node a: [a w_x(a) ×4, w'_x(a) ×4].
        Double8 m1[W];
        for (int a = 0; a < W; ++a) {
            const double awx = a * s.w[0][a], dwx = s.dw[0][a];
            m1[a] = Double8{awx, awx, awx, awx, dwx, dwx, dwx, dwx};
        }
        // One row of the stencil: weight w_r and derivatives ∂_y w_r, ∂_z w_r; offsets oy, oz.
        auto row = [&](Index first, double wr, double dy, double dz, double oy, double oz) {
            Double4 r0 = none, r1 = none, f0 = none, f1 = none;
            if constexpr (Momentum) r0 = wr * (P + oy * Q[1] + oz * Q[2]);
            if constexpr (Momentum && Affine) r1 = wr * Q[0];
            if constexpr (Stress) {
                f0 = dy * T[1] + dz * T[2];
                f1 = wr * T[0];
            }
            const Double8 x0 = join(r0, f0), x1 = join(r1, f1);
            for (int a = 0; a < W; ++a) {
                NodeLine& q = lines[first + o[0][a]];
                Double8 x = load(q) + s.w[0][a] * x0;
                x += m1[a] * x1;
                store(q, x);
            }
        };
        forRows(s, o, row);
    }

    /// Visit the lines of the active blocks, block by block in parallel: fn(node, line).
    template <class Fn> static void forActiveLines(const NodeFields<dim>& g, Fn&& fn) {
        const auto& active = g.activeBlocks();
        const Index na = static_cast<Index>(active.size());
        constexpr Index Nb = Grid<dim>::NodesPerBlock;
#pragma omp parallel for if (worthThreads(Nb * na)) schedule(static)
        for (Index k = 0; k < na; ++k)
            for (Index n = active[k] * Nb; n < (active[k] + 1) * Nb; ++n)
                fn(n, g.lines[n]);
    }

    /// P2G: the active lines zeroed, every particle scattered into them (scatterOne; blocks of
    /// one colour in parallel, colours in turn), then the sums added to the node fields.
    template <bool Momentum, bool Stress>
    void scatterImpl(const PointFields<dim>& p, const NodeFields<dim>& g,
                     const BlockSort<dim>& sort) {
        forActiveLines(g, [](Index, NodeLine& q) { q = NodeLine{}; });
        const double h = g.h();
        const double invH = g.invH();
        const auto& order = sort.order();
        NodeLine* lines = g.lines;
        assert(p.x == points_.x && "scatter of other points than computeWeights'");
        // P2G reads the points in block order (order[]), whose jumps the hardware prefetchers do
        // not follow: the fields it reads are fetched `Ahead` points early (block2D P2G −10 to
        // −16 %, docs/benchmarks.md).
        constexpr Index Ahead = 8;
        auto prefetchPoint = [this, &p](Index f, auto evaluating) {
            if constexpr (decltype(evaluating)::value)
                __builtin_prefetch(&p.x[f]);
            else
                __builtin_prefetch(&st_[f]);
            if constexpr (Momentum) {
                __builtin_prefetch(&p.mass[f]);
                __builtin_prefetch(&p.v[f]);
                if constexpr (Affine) __builtin_prefetch(&p.C[f]);
            }
            if constexpr (Stress) {
                __builtin_prefetch(&p.volume[f]);
                __builtin_prefetch(&p.stress[f]);
            }
        };
        auto scatterPoint = [&](const Stencil& s, Index i) {
            const double m = p.mass[i];
            Mat<dim> mC = Mat<dim>::Zero();
            if constexpr (Affine) mC = (m * h) * p.C[i];
            Mat<dim> stressTerm = Mat<dim>::Zero();
            if constexpr (Stress)
                stressTerm = (-p.volume[i] * invH) * p.stress[i].template topLeftCorner<dim, dim>();
            scatterOne<Momentum, Stress>(s, lines, m, m * p.v[i], mC, stressTerm);
        };
        // The step's first scatter evaluates the stencils (chosen once, not per point), scatters
        // from registers and streams them to st_ for the later transfers: the stencil lines are
        // written without being read first (P2G −13 to −22 % in block2D, docs/benchmarks.md).
        auto scatterAll = [&](auto evaluateFirst) {
            sort.forEachBlockByColour(worthThreads(static_cast<Index>(p.size())),
                                      [&](Index, auto r) {
                                          for (Index j = r.begin; j < r.end; ++j) {
                                              const Index i = order[j];
                                              if (j + Ahead < r.end)
                                                  prefetchPoint(order[j + Ahead], evaluateFirst);
                                              if constexpr (decltype(evaluateFirst)::value) {
                                                  Stencil s;
                                                  evaluate(i, s);
                                                  scatterPoint(s, i);
                                                  streamStore(st_[i], s);
                                              } else {
                                                  scatterPoint(st_[i], i);
                                              }
                                          }
                                          if constexpr (decltype(evaluateFirst)::value) sfence();
                                      });
        };
        if (pending_)
            scatterAll(std::true_type{});
        else
            scatterAll(std::false_type{});
        pending_ = false;
        forActiveLines(g, [&g](Index n, const NodeLine& q) {
            if constexpr (Momentum) {
                g.mass[n] += q.v[0];
                for (int d = 0; d < dim; ++d)
                    g.momentum[n][d] += q.v[1 + d];
            }
            if constexpr (Stress)
                for (int d = 0; d < dim; ++d)
                    g.force[n][d] += q.v[4 + d];
        });
    }

    template <bool Grad, bool Flip>
    GatherStats gatherImpl(const PointFields<dim>& p, const NodeFields<dim>& g, double dt) {
        forActiveLines(g, [&g](Index k, NodeLine& q) {
            q = NodeLine{};
            for (int d = 0; d < dim; ++d) {
                q.v[d] = g.v[k][d];
                if constexpr (Flip) q.v[4 + d] = g.v[k][d] - g.vOld[k][d];
            }
        });
        const NodeLine* lines = g.lines;
        const Index n = p.size();
        const double invH = g.invH();
        const double eta = ratio_;
        double vmax2 = 0.0, move2 = 0.0, ke = 0.0;
        Index bad = n, mover = -1;
#pragma omp parallel if(worthThreads(n)) reduction(max : vmax2) reduction(+ : ke) \
    reduction(min : bad)
        {
            // The fastest-moving point: each thread's first of its fastest, then the fastest of
            // those, the lowest index of equals (the same point on any number of threads).
            double myMove2 = 0.0;
            Index myMover = -1;
#pragma omp for schedule(static) nowait
            for (Index i = 0; i < n; ++i) {
                const Stencil& s = st_[i];
                Vec<dim> vPic = Vec<dim>::Zero();
                Vec<dim> dv = Vec<dim>::Zero();
                Mat<dim> B = Mat<dim>::Zero();
                Mat<dim> L = Mat<dim>::Zero();
                gatherLines<Grad, Flip>(s, lines, vPic, dv, B, L);
                // New v and x from registers: the checks below do not re-read the stores.
                Vec<dim> v = vPic;
                if constexpr (Affine)
                    streamValue(p.C[i], Mat<dim>(B * (invH / K::InertiaFactor)));
                else if constexpr (Flip)
                    v = eta * (p.v[i] + dv) + (1.0 - eta) * vPic;
                p.v[i] = v;
                if constexpr (Grad) streamValue(p.L[i], Mat<dim>(L * invH));
                const Vec<dim> x = p.x[i] + dt * vPic;
                p.x[i] = x;
                if (const double m2 = vPic.squaredNorm(); m2 > myMove2) {
                    myMove2 = m2;
                    myMover = i;
                }
                const double v2 = v.squaredNorm();
                if (!std::isfinite(v2) || !std::isfinite(x.sum())) bad = std::min(bad, i);
                vmax2 = std::max(vmax2, v2);
                ke += 0.5 * p.mass[i] * v2;
            }
            sfence(); // C and L streamed
#pragma omp critical(fastestMoving)
            if (myMove2 > move2 || (myMove2 == move2 && myMover >= 0 && myMover < mover)) {
                move2 = myMove2;
                mover = myMover;
            }
        }
        GatherStats st;
        st.maxSpeed = std::sqrt(vmax2);
        st.maxMoveSpeed = std::sqrt(move2);
        st.fastestMoving = mover;
        st.kineticEnergy = ke;
        st.firstNonFinite = bad < n ? bad : -1;
        return st;
    }

    K kernel_;
    double ratio_;
    mutable std::vector<Stencil> st_;
    NodeFields<dim> grid_;         ///< the node numbering (axisOffset) of computeWeights
    PointFields<dim> points_;      ///< the points of computeWeights (their x^n)
    mutable bool pending_ = false; ///< st_ not yet evaluated for this step
};

/// APIC needs a kernel with constant inertia D_p (its `InertiaFactor`: the quadratic and cubic
/// B-splines).
template <class K, class = void> struct HasInertia : std::false_type {};
template <class K>
struct HasInertia<K, std::void_t<decltype(K::InertiaFactor)>> : std::true_type {};

/// A kernel that takes the particle half-width (GIMP's l_p / h).
template <class K, class = void> struct HasHalfWidth : std::false_type {};
template <class K> struct HasHalfWidth<K, std::void_t<decltype(K::l)>> : std::true_type {};

/// What a transfer scheme (system/mpmSchemes `transfer`, the family `transfers`) asks of the
/// gather: the affine terms (APIC) or the FLIP/PIC blend with ratio η (PIC: η = 0). A scheme
/// registers in TransferSchemeRegistry, built from the `transfer:` map (`map` true) or from the
/// word alone (`map` false: its keys take their defaults, and `dict` is system/mpmSchemes, which
/// it must not read).
struct TransferScheme {
    bool affine = false;
    double ratio = 0.0;
    virtual ~TransferScheme() = default;
};
using TransferSchemeRegistry = Registry<TransferScheme, bool>;

struct PicScheme final : TransferScheme {
    PicScheme(const Dictionary&, bool) {}
};
struct FlipScheme final : TransferScheme {
    FlipScheme(const Dictionary& dict, bool map) {
        ratio = map ? dict.getScalarOr("ratio", 0.995, Bounds::closed(0.0, 1.0)) : 0.995;
    }
};
struct ApicScheme final : TransferScheme {
    ApicScheme(const Dictionary&, bool) { affine = true; }
};

template <int dim> using KernelRegistry = Registry<KernelChoice<dim>, double>;

/// The kernel K as registered: built with the particle half-width l_p/h (GIMP's; clipped to
/// 0.49), it describes itself to any backend and instantiates the cpu backend's loops for K.
template <int dim, class K> class KernelOf final : public KernelChoice<dim> {
public:
    KernelOf(const Dictionary&, double particleHalfWidth) {
        if constexpr (HasHalfWidth<K>::value) kernel_.l = std::min(particleHalfWidth, 0.49);
    }
    KernelFunction function() const override {
        KernelFunction f;
        f.name = K::Name;
        f.width = K::Width;
        if constexpr (HasHalfWidth<K>::value) f.halfWidth = kernel_.l;
        if constexpr (HasInertia<K>::value) f.inertiaFactor = K::InertiaFactor;
        f.eval = [k = kernel_](double xh, double* w, double* dw) { return k.eval(xh, w, dw); };
        return f;
    }
    std::unique_ptr<Transfer<dim>> makeCpu(const TransferOptions& options) const override {
        if (!options.affine)
            return std::make_unique<TransferImpl<dim, K, false>>(kernel_, options.ratio);
        if constexpr (HasInertia<K>::value)
            return std::make_unique<TransferImpl<dim, K, true>>(kernel_, 0.0);
        else
            throw std::logic_error("internal error: APIC without a constant inertia");
    }

private:
    K kernel_;
};

/// The optimised loops of this file (`backend: cpu`, the default).
template <int dim> struct CpuBackend final : Backend<dim> {
    explicit CpuBackend(const Dictionary&) {}
    std::unique_ptr<Transfer<dim>> make(const KernelChoice<dim>& kernel,
                                        const TransferOptions& options) const override {
        return kernel.makeCpu(options);
    }
};

} // namespace

/// Register the kernel type K (src/kernels/Kernels.hpp) under K::Name in 2D and 3D, with its
/// transfers: MPM_REGISTER_KERNEL(LinearKernel).
#define MPM_REGISTER_KERNEL(K)                                                                     \
    static const KernelRegistry<2>::Add MPM_CONCAT(mpmKernel, __COUNTER__)(                        \
        K::Name, [](const Dictionary& d, double l) {                                               \
            return std::unique_ptr<KernelChoice<2>>(new KernelOf<2, K>(d, l));                     \
        });                                                                                        \
    static const KernelRegistry<3>::Add MPM_CONCAT(mpmKernel, __COUNTER__)(                        \
        K::Name, [](const Dictionary& d, double l) {                                               \
            return std::unique_ptr<KernelChoice<3>>(new KernelOf<3, K>(d, l));                     \
        })

MPM_FAMILY_INFO("kernels", {"kernel in system/mpmSchemes (a word)", "3. system/mpmSchemes", {}});
MPM_FAMILY_DIMS(KernelRegistry, "kernels");
MPM_REGISTER_KERNEL(LinearKernel);
MPM_SCHEMA("kernels", "linear",
           {"linear hat functions (C0; grid-crossing noise)", {}, "kernel: linear"});
MPM_REGISTER_KERNEL(GimpKernel);
MPM_SCHEMA("kernels", "gimp",
           {"generalised interpolation MPM, the particle half-width from the seeding",
            {},
            "kernel: gimp"});
MPM_REGISTER_KERNEL(QuadraticBSplineKernel);
MPM_SCHEMA("kernels", "quadraticBSpline",
           {"quadratic B-spline (C1; APIC's constant inertia)", {}, "kernel: quadraticBSpline"});
MPM_REGISTER_KERNEL(CubicBSplineKernel);
MPM_SCHEMA("kernels", "cubicBSpline",
           {"cubic B-spline (C2; APIC's constant inertia)", {}, "kernel: cubicBSpline"});

// Transfer schemes serve both dimensions: the family's registry of dimension 0.
MPM_FAMILY_INFO("transfers",
                {"transfer in system/mpmSchemes (a word, or a map with type)",
                 "3. system/mpmSchemes",
                 {{"type", "word", "-", "required", "the transfer (in the map form)"}}});
MPM_FAMILY(TransferSchemeRegistry, 0, "transfers");
MPM_REGISTER(TransferSchemeRegistry, PicScheme, "pic");
MPM_SCHEMA("transfers", "pic",
           {"particle-in-cell: the points take the grid velocity", {}, "transfer: pic"});
MPM_REGISTER(TransferSchemeRegistry, FlipScheme, "flip");
MPM_SCHEMA("transfers", "flip",
           {"PIC/FLIP blend: the points take a fraction η of the grid's velocity change",
            {{"ratio", "scalar", "-", "0.995", "FLIP fraction η, in [0, 1]"}},
            "transfer: {type: flip, ratio: 0.99}"});
MPM_REGISTER(TransferSchemeRegistry, ApicScheme, "apic");
MPM_SCHEMA("transfers", "apic",
           {"affine PIC (quadraticBSpline or cubicBSpline kernels)", {}, "transfer: apic"});

MPM_FAMILY_INFO("backends",
                {"backend in system/mpmSchemes (a word; default cpu)", "3. system/mpmSchemes", {}});
MPM_FAMILY_DIMS(BackendRegistry, "backends");
MPM_REGISTER_DIMS(BackendRegistry, CpuBackend, "cpu");
MPM_SCHEMA("backends", "cpu",
           {"the optimised loops: stencils factored per row, SIMD node lines, blocks by colour "
            "on OpenMP threads (the default)",
            {},
            "backend: cpu"});

template <int dim>
std::unique_ptr<Transfer<dim>> Transfer<dim>::create(const Dictionary& schemes,
                                                     double particleHalfWidth) {
    // Chosen once: the kernel's transfer loops are instantiated for the kernel type.
    const std::unique_ptr<KernelChoice<dim>> kernel =
        selectByWord<KernelRegistry<dim>>(schemes, "kernel", "", particleHalfWidth);
    const std::unique_ptr<TransferScheme> scheme =
        schemes.isDict("transfer")
            ? TransferSchemeRegistry::create(schemes.subDict("transfer"), true)
            : selectByWord<TransferSchemeRegistry>(schemes, "transfer", "", false);
    const KernelFunction f = kernel->function();
    if (scheme->affine && !(f.inertiaFactor > 0))
        schemes.error("transfer",
                      "apic needs kernel quadraticBSpline or cubicBSpline (constant D_p), not " +
                          f.name);
    const std::unique_ptr<Backend<dim>> backend =
        selectByWord<BackendRegistry<dim>>(schemes, "backend", "cpu");
    return backend->make(*kernel, TransferOptions{scheme->affine, scheme->ratio});
}

template class Transfer<2>;
template class Transfer<3>;

} // namespace mpm
