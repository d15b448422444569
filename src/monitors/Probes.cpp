// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/Log.hpp"
#include "monitors/FunctionObject.hpp"

#include <algorithm>
#include <array>
#include <functional>
#include <sstream>

namespace mpm {

/// `type: probes`: material point fields at fixed points (OpenFOAM's probes). The value at a
/// probe x_k is the Shepard (normalised, mass-weighted) average of the point values within the
/// radius R,
///     f(x_k) = Σ w m_p f_p / Σ w m_p,  w = (1 − (r/R)²)² for r = |x_p − x_k| < R, else 0,
/// which reproduces a constant field exactly, and a linear one on a point set symmetric about
/// x_k. A probe with no point within R writes 0 (and warns once).
///
/// Keys: `fields` (default [pressure]): `pressure` −tr σ/3 [Pa], `density` m/V [kg/m³],
/// `velocity` [m/s] (columns vx vy (vz)), `stress` σ [Pa] (columns xx yy zz xy (yz xz)),
/// `plasticStrain` [-], or the name of any declared model scalar state; `probeLocations`
/// (required, dim coordinates each, inside the grid box) [m]; `radius` R (default 1.5 h) [m].
/// Columns `<field>_<k>` (scalars) and `<component>_<k>` (vectors, tensors), field by field,
/// probe k = 0, 1, … within each field. The sums run over fixed chunks of points added in
/// chunk order (the same for any thread count), only when a row is written: O(N × probes).
template <int dim> class Probes final : public FunctionObject<dim> {
public:
    Probes(const Dictionary& dict, const std::string& name)
        : FunctionObject<dim>(dict, name),
          names_(dict.has("fields") ? dict.getStringList("fields")
                                    : std::vector<std::string>{"pressure"}),
          radius_(dict.has("radius") ? dict.getScalar("radius", Bounds::positive()) : 0.0) {
        if (names_.empty()) dict.error("fields", "expected at least one field name");
        for (std::size_t a = 0; a < names_.size(); ++a)
            for (std::size_t b = 0; b < a; ++b)
                if (names_[a] == names_[b])
                    dict.error("fields", "field '" + names_[a] + "' is listed twice");
        for (const auto& row : dict.vectorList("probeLocations", dim)) {
            Vec<dim> x;
            for (int d = 0; d < dim; ++d)
                x[d] = row[d];
            probes_.push_back(x);
        }
        if (probes_.empty()) dict.error("probeLocations", "expected at least one probe location");
        warned_.assign(probes_.size(), 0);
    }

protected:
    void initialise(const State<dim>& s, const Time&) override {
        const Grid<dim>& g = s.grid;
        for (std::size_t k = 0; k < probes_.size(); ++k) {
            bool inside = true;
            for (int d = 0; d < dim; ++d)
                inside = inside && probes_[k][d] >= g.lo()[d] && probes_[k][d] <= g.hi()[d];
            if (!inside) {
                this->dict().error("probeLocations",
                                   "probe " + std::to_string(k) + " " + point(probes_[k]) +
                                       " is outside the grid box " + point(g.lo()) + " to " +
                                       point(g.hi()) + " of constant/grid");
            }
        }
        if (radius_ <= 0) radius_ = 1.5 * g.h();

        const auto& p = s.particles;
        fields_.clear();
        width_ = 0;
        const std::vector<Field> known = pointFields();
        for (const auto& n : names_) {
            const auto builtIn = std::find_if(known.begin(), known.end(),
                                              [&n](const Field& k) { return k.name == n; });
            Field f;
            if (builtIn != known.end()) {
                f = *builtIn;
            } else {
                const auto it = std::find_if(p.scalars.begin(), p.scalars.end(),
                                             [&n](const auto& sf) { return sf.info.name == n; });
                if (it == p.scalars.end()) {
                    std::string valid;
                    for (const Field& k : known)
                        valid += (valid.empty() ? "" : ", ") + k.name;
                    for (const auto& sf : p.scalars)
                        valid += ", " + sf.info.name;
                    this->dict().error("fields",
                                       "unknown field '" + n + "' (valid: " + valid + ")");
                }
                const std::size_t handle = static_cast<std::size_t>(it - p.scalars.begin());
                f = {n, {}, [handle](const Particles<dim>& q, Index i, double wm, double* acc) {
                         acc[0] += wm * q.scalar(handle)[i];
                     }};
            }
            width_ += std::max<int>(1, static_cast<int>(f.components.size()));
            fields_.push_back(std::move(f));
        }
    }

    std::vector<std::string> headerLines(const State<dim>&) const override {
        std::vector<std::string> lines;
        for (std::size_t k = 0; k < probes_.size(); ++k)
            lines.push_back("probe " + std::to_string(k) + ": " + point(probes_[k]));
        lines.push_back("radius: " + number(radius_));
        return lines;
    }

    std::vector<std::string> columns(const State<dim>&) const override {
        std::vector<std::string> c;
        for (const auto& f : fields_)
            for (std::size_t k = 0; k < probes_.size(); ++k) {
                if (f.components.empty()) c.push_back(f.name + "_" + std::to_string(k));
                for (const auto& comp : f.components)
                    c.push_back(comp + "_" + std::to_string(k));
            }
        return c;
    }

    std::vector<double> values(const State<dim>& s) const override {
        const auto& p = s.particles;
        const Index n = static_cast<Index>(p.size());
        const std::size_t np = probes_.size();
        // Per probe: Σ w m, then Σ w m f for every component of every field.
        const std::size_t stride = 1 + static_cast<std::size_t>(width_);
        constexpr Index chunk = 4096;
        const Index nChunks = (n + chunk - 1) / chunk;
        std::vector<double> partial(static_cast<std::size_t>(nChunks) * np * stride, 0.0);
        const double R2 = radius_ * radius_;
#pragma omp parallel for if (worthThreads(n)) schedule(static)
        for (Index c = 0; c < nChunks; ++c) {
            double* acc = partial.data() + static_cast<std::size_t>(c) * np * stride;
            const Index end = std::min(n, (c + 1) * chunk);
            for (Index i = c * chunk; i < end; ++i)
                for (std::size_t k = 0; k < np; ++k) {
                    const double r2 = (p.x[i] - probes_[k]).squaredNorm();
                    if (!(r2 < R2)) continue;
                    const double q = 1.0 - r2 / R2;
                    const double wm = q * q * p.mass[i];
                    double* a = acc + k * stride;
                    a[0] += wm;
                    accumulate(p, i, wm, a + 1);
                }
        }
        std::vector<double> sum(np * stride, 0.0);
        for (Index c = 0; c < nChunks; ++c)
            for (std::size_t j = 0; j < sum.size(); ++j)
                sum[j] += partial[static_cast<std::size_t>(c) * np * stride + j];
        s.comm.sum(sum.data(), static_cast<int>(sum.size())); // every rank's points

        for (std::size_t k = 0; k < np; ++k)
            if (!(sum[k * stride] > 0) && !warned_[k]) {
                warned_[k] = 1;
                warning() << "probes '" << this->name() << "': probe " << k << " "
                          << point(probes_[k]) << " has no material point within radius " << radius_
                          << " m at t = " << s.time
                          << " s; its values are written as 0 (warned once per probe)\n";
            }
        std::vector<double> row;
        row.reserve(np * static_cast<std::size_t>(width_));
        int offset = 1;
        for (const auto& f : fields_) {
            const int nc = std::max<int>(1, static_cast<int>(f.components.size()));
            for (std::size_t k = 0; k < np; ++k) {
                const double w = sum[k * stride];
                for (int j = 0; j < nc; ++j)
                    row.push_back(w > 0 ? sum[k * stride + offset + j] / w : 0.0);
            }
            offset += nc;
        }
        return row;
    }

private:
    /// A sampled field: its name, column prefixes (empty: a scalar) and what a point adds,
    /// acc[j] += wm f_j for each of its components j.
    struct Field {
        std::string name;
        std::vector<std::string> components;
        std::function<void(const Particles<dim>&, Index, double, double*)> add;
    };
    /// Independent stress components: xx yy zz xy, and yz xz in 3D (σ_zz is carried in 2D).
    static constexpr int numStress = dim == 3 ? 6 : 4;
    static constexpr std::array<const char*, 6> stressNames{"xx", "yy", "zz", "xy", "yz", "xz"};
    static constexpr std::array<std::array<int, 2>, 6> stressIndex{
        {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}}};

    /// The fields every point has (a model scalar state is sampled by its own name).
    static std::vector<Field> pointFields() {
        std::vector<std::string> v, sigma;
        for (int d = 0; d < dim; ++d)
            v.push_back(std::string("v") + "xyz"[d]);
        for (int c = 0; c < numStress; ++c)
            sigma.push_back(stressNames[c]);
        using P = const Particles<dim>&;
        return {
            {"pressure",
             {},
             [](P p, Index i, double wm, double* a) { a[0] += wm * (-p.stress[i].trace() / 3.0); }},
            {"density",
             {},
             [](P p, Index i, double wm, double* a) { a[0] += wm * (p.mass[i] / p.volume[i]); }},
            {"velocity", v,
             [](P p, Index i, double wm, double* a) {
                 for (int d = 0; d < dim; ++d)
                     a[d] += wm * p.v[i][d];
             }},
            {"stress", sigma,
             [](P p, Index i, double wm, double* a) {
                 for (int c = 0; c < numStress; ++c)
                     a[c] += wm * p.stress[i](stressIndex[c][0], stressIndex[c][1]);
             }},
            {"plasticStrain",
             {},
             [](P p, Index i, double wm, double* a) { a[0] += wm * p.plasticStrain[i]; }},
        };
    }

    /// a[j] += wm f_j for every component j of every field at point i, in column order.
    void accumulate(const Particles<dim>& p, Index i, double wm, double* a) const {
        for (const auto& f : fields_) {
            f.add(p, i, wm, a);
            a += std::max<std::size_t>(1, f.components.size());
        }
    }

    static std::string number(double v) {
        std::ostringstream os;
        os.precision(10);
        os << v;
        return os.str();
    }
    static std::string point(const Vec<dim>& x) {
        std::string s = "(";
        for (int d = 0; d < dim; ++d)
            s += (d > 0 ? ", " : "") + number(x[d]);
        return s + ")";
    }

    std::vector<std::string> names_;
    double radius_; ///< R [m]; 0 until initialise() when not given (then 1.5 h)
    std::vector<Vec<dim>> probes_;
    std::vector<Field> fields_;
    int width_ = 0;                    ///< columns per probe (all fields' components)
    mutable std::vector<char> warned_; ///< probe k was reported empty
};

MPM_REGISTER_DIMS(FunctionObjectRegistry, Probes, "probes");
MPM_SCHEMA("functionObjects", "probes",
           {"material point fields at fixed points (mass-weighted Shepard average)",
            {{"probeLocations", "list of vectors", "m", "required",
              "the probes, each inside the grid box"},
             {"fields", "list of words", "-", "[pressure]",
              "pressure density velocity stress plasticStrain, or a model scalar"},
             {"radius", "scalar", "m", "1.5 h", "sampling radius R (> 0)"}},
            "{type: probes, probeLocations: [[0.1, 0.05]], fields: [pressure, velocity]}"});

} // namespace mpm
