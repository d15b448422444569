// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/Log.hpp"
#include "core/PointBins.hpp"
#include "monitors/FunctionObject.hpp"

#include <cmath>
#include <cstring>
#include <sstream>

namespace mpm {

/// `type: isolatedPoints`: the material points with no other point within a distance r
/// (`radius`, default the cell size h) [m]: points that fly alone, a gas of points rather than
/// a continuum. A point stands for a piece of material only among neighbours; alone, its
/// stress and velocity gradient come from its own motion. Columns `isolated` (count) and
/// `fraction` (of all points). The first row whose fraction exceeds `warnAbove` (default 0.05)
/// prints a warning. A dense material has none; a granular layer thrown up by a vibrating plate
/// under pure FLIP has 8–12 % (cases/vibratedLayer README, "Pure FLIP turns the layer into a
/// gas"). Cells of size r hash the points, so the cost is O(N) per row; in a parallel run every
/// rank gathers all the points (a diagnostic, written rarely).
template <int dim> class IsolatedPoints final : public FunctionObject<dim> {
public:
    IsolatedPoints(const Dictionary& dict, const std::string& name)
        : FunctionObject<dim>(dict, name),
          radius_(dict.getScalarOr("radius", 0.0, Bounds::positive())),
          warnAbove_(dict.getScalarOr("warnAbove", 0.05, Bounds::closed(0.0, 1.0))) {}

protected:
    void initialise(const State<dim>& s, const Time&) override {
        if (!(radius_ > 0)) radius_ = s.grid.h();
    }
    std::vector<std::string> headerLines(const State<dim>&) const override {
        std::ostringstream os;
        os << "points with no other point within r = " << radius_ << " m";
        return {os.str()};
    }
    std::vector<std::string> columns(const State<dim>&) const override {
        return {"isolated", "fraction"};
    }
    std::vector<double> values(const State<dim>& s) const override {
        const std::vector<Vec<dim>> x = allPositions(s);
        const double isolated = static_cast<double>(countIsolated(x));
        const double fraction = x.empty() ? 0.0 : isolated / static_cast<double>(x.size());
        if (fraction > warnAbove_ && !warned_) {
            warned_ = true;
            warning() << "t = " << s.time << " s: " << 100 * fraction << " % of the points have "
                      << "no other point within " << radius_ << " m (function object '"
                      << this->name() << "'): the material flies apart as single points, a gas "
                      << "rather than a continuum (pure FLIP? see docs/caseFormat.md)\n";
        }
        return {isolated, fraction};
    }

private:
    /// Every rank's points (a serial run: its own).
    static std::vector<Vec<dim>> allPositions(const State<dim>& s) {
        const auto& p = s.particles;
        std::vector<Vec<dim>> x(p.x.begin(), p.x.end());
        if (!s.comm.parallel()) return x;
        std::vector<char> mine(x.size() * sizeof(Vec<dim>));
        if (!x.empty()) std::memcpy(mine.data(), static_cast<const void*>(x.data()), mine.size());
        const auto recv = s.comm.exchange(
            std::vector<std::vector<char>>(static_cast<std::size_t>(s.comm.size()), mine));
        x.clear();
        for (const auto& bytes : recv) {
            const std::size_t at = x.size();
            x.resize(at + bytes.size() / sizeof(Vec<dim>));
            if (!bytes.empty())
                std::memcpy(static_cast<void*>(x.data() + at), bytes.data(), bytes.size());
        }
        return x;
    }

    /// Points with no other point within radius_: cells of size ≥ r, the 3^dim block around each.
    std::size_t countIsolated(const std::vector<Vec<dim>>& x) const {
        const PointBins<dim> bins(x, radius_);
        const double r2 = radius_ * radius_;
        std::size_t isolated = 0;
        for (std::size_t i = 0; i < x.size(); ++i)
            isolated += !bins.anyNear(x[i], 1, [&](std::size_t j) {
                return j != i && (x[j] - x[i]).squaredNorm() <= r2;
            });
        return isolated;
    }

    double radius_;
    double warnAbove_;
    mutable bool warned_ = false;
};

MPM_REGISTER_DIMS(FunctionObjectRegistry, IsolatedPoints, "isolatedPoints");
MPM_SCHEMA("functionObjects", "isolatedPoints",
           {"points with no other point within a radius (a gas of points)",
            {{"radius", "scalar", "m", "h", "neighbour radius r (> 0)"},
             {"warnAbove", "scalar", "-", "0.05",
              "warn once when the fraction exceeds it, in [0, 1]"}},
            "{type: isolatedPoints, radius: 0.01}"});

} // namespace mpm
