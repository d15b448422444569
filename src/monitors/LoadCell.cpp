// SPDX-License-Identifier: GPL-3.0-or-later
#include "monitors/FunctionObject.hpp"

#include <deque>

namespace mpm {

/// `type: loadCell`: the force the material exerts on one grid face (`face: zMin`), like the
/// load cell under the sand box [000 §4.2]: the raw value of the step and its moving average
/// over the last `window` seconds (default 0: no averaging), weighted by the step sizes.
/// Columns: the face-normal load (positive pushing outward on the face, e.g. the weight on
/// zMin), its average, then the raw force components. Sampled every step, whatever the write
/// interval.
template <int dim> class LoadCell final : public FunctionObject<dim> {
public:
    LoadCell(const Dictionary& dict, const std::string& name) : FunctionObject<dim>(dict, name) {
        std::vector<std::string> faces;
        for (int f = 0; f < 2 * dim; ++f)
            faces.push_back(Grid<dim>::faceName(f));
        const std::string face = dict.getWord("face", faces);
        for (int f = 0; f < 2 * dim; ++f)
            if (faces[f] == face) face_ = f;
        window_ = dict.getScalarOr("window", 0.0, Bounds::nonNegative());
    }
    std::string needsStep() const override {
        return "needs every time step's grid update (the face's reaction and its average)";
    }

protected:
    void sample(const State<dim>& s, const Time& time) override {
        const Vec<dim>& F = s.reactions[face_];
        // Outward normal of the face: -e on a Min face, +e on a Max face.
        const double sign = face_ % 2 == 0 ? -1.0 : 1.0;
        load_ = sign * F[face_ / 2];
        raw_ = F;
        samples_.push_back({time.value(), time.deltaT(), load_});
        sum_ += time.deltaT() * load_;
        weight_ += time.deltaT();
        while (samples_.size() > 1 && samples_.front().t <= time.value() - window_) {
            sum_ -= samples_.front().dt * samples_.front().load;
            weight_ -= samples_.front().dt;
            samples_.pop_front();
        }
    }
    std::vector<std::string> columns(const State<dim>&) const override {
        std::vector<std::string> c{"load", "loadAverage"};
        const char* axes = "xyz";
        for (int d = 0; d < dim; ++d)
            c.push_back(std::string("F") + axes[d]);
        return c;
    }
    std::vector<double> values(const State<dim>&) const override {
        std::vector<double> v{load_, weight_ > 0 ? sum_ / weight_ : load_};
        for (int d = 0; d < dim; ++d)
            v.push_back(raw_[d]);
        return v;
    }

private:
    struct Sample {
        double t, dt, load;
    };
    int face_ = 0;
    double window_ = 0;
    std::deque<Sample> samples_;
    double sum_ = 0, weight_ = 0, load_ = 0;
    Vec<dim> raw_ = Vec<dim>::Zero();
};

MPM_REGISTER_DIMS(FunctionObjectRegistry, LoadCell, "loadCell");
MPM_SCHEMA("functionObjects", "loadCell",
           {"one face's reaction and its moving average, sampled every step",
            {{"face", "word", "-", "required", "the face: xMin xMax yMin yMax (zMin zMax in 3D)"},
             {"window", "scalar", "s", "0", "averaging window (≥ 0; 0: the raw value)"}},
            "{type: loadCell, face: yMin, window: 0.01}"});

} // namespace mpm
