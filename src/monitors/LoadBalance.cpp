// SPDX-License-Identifier: GPL-3.0-or-later
#include "monitors/FunctionObject.hpp"

#include <algorithm>

namespace mpm {

/// `type: loadBalance`: how evenly the ranks of a parallel run share the points (docs/parallel.md):
/// columns ranks, the largest and the smallest rank's points over the mean, and those two counts.
/// A serial run has one rank and the ratios 1.
template <int dim> class LoadBalance final : public FunctionObject<dim> {
public:
    LoadBalance(const Dictionary& dict, const std::string& name)
        : FunctionObject<dim>(dict, name) {}
    std::string needsStep() const override {
        return "needs the running ranks (their share of the points is not written)";
    }

protected:
    std::vector<std::string> columns(const State<dim>&) const override {
        return {"ranks", "maxOverMean", "minOverMean", "maxPoints", "minPoints"};
    }
    std::vector<double> values(const State<dim>& s) const override {
        const std::vector<double> n = s.comm.gather(static_cast<double>(s.particles.size()));
        double sum = 0;
        for (double x : n)
            sum += x;
        const double mean = sum / static_cast<double>(n.size());
        const double most = *std::max_element(n.begin(), n.end());
        const double least = *std::min_element(n.begin(), n.end());
        return {static_cast<double>(n.size()), mean > 0 ? most / mean : 1.0,
                mean > 0 ? least / mean : 1.0, most, least};
    }
};

MPM_REGISTER_DIMS(FunctionObjectRegistry, LoadBalance, "loadBalance");
MPM_SCHEMA("functionObjects", "loadBalance",
           {"how evenly the ranks of a parallel run share the points", {}, "{type: loadBalance}"});

} // namespace mpm
