// SPDX-License-Identifier: GPL-3.0-or-later
#include "monitors/FunctionObject.hpp"

#include <cmath>
#include <filesystem>
#include <iomanip>

namespace mpm {

template <int dim>
FunctionObject<dim>::FunctionObject(const Dictionary& dict, std::string name)
    : dict_(dict), name_(std::move(name)) {
    const std::string wc = dict.getWordOr("writeControl", "timeStep", {"timeStep", "runTime"});
    byTime_ = wc == "runTime";
    interval_ = byTime_ ? dict.getScalarOr("writeInterval", 0.0, Bounds::nonNegative())
                        : dict.getIntOr("writeInterval", 1, Bounds::closed(1, 2e9));
}

template <int dim>
std::filesystem::path FunctionObject<dim>::file(const Case& cs, const Time& time) const {
    return cs.path("postProcessing") / name_ / timeName(time.value(), 6) / (name_ + ".dat");
}

template <int dim> void FunctionObject<dim>::open(const Case& cs, const Time& time, bool write) {
    if (write) {
        const auto path = file(cs, time);
        std::filesystem::create_directories(path.parent_path());
        out_.open(path);
        if (!out_) throw RunError("cannot write " + path.string());
    }
    precision_ = std::max(time.writePrecision(), 10);
    // The index execute() compares with (a restarted run resumes the same schedule).
    lastIndex_ = byTime_ ? static_cast<long>(std::floor(time.value() / std::max(interval_, 1e-300)))
                         : time.index() / static_cast<long>(interval_);
}

template <int dim> void FunctionObject<dim>::executeNow(const State<dim>& s, const Time& time) {
    const std::vector<double> row = values(s); // collective in a parallel run
    if (!out_.is_open()) return;               // ranks other than 0 of a parallel run
    if (!headerDone_) {
        out_ << "# " << name_ << '\n';
        for (const auto& l : headerLines(s))
            out_ << "# " << l << '\n';
        out_ << "# time";
        for (const auto& c : columns(s))
            out_ << ' ' << c;
        out_ << '\n';
        headerDone_ = true;
    }
    out_ << std::setprecision(precision_) << std::scientific << time.value();
    for (double v : row)
        out_ << ' ' << v;
    out_ << '\n';
    out_.flush();
}

template <int dim> void FunctionObject<dim>::execute(const State<dim>& s, const Time& time) {
    sample(s, time);
    long idx = 0;
    if (byTime_)
        idx = interval_ > 0 ? static_cast<long>(std::floor(time.value() / interval_ + 1e-8))
                            : time.index();
    else
        idx = time.index() / static_cast<long>(interval_);
    if (idx <= lastIndex_) return;
    lastIndex_ = idx;
    executeNow(s, time);
}

template <int dim>
std::vector<std::unique_ptr<FunctionObject<dim>>>
FunctionObject<dim>::createAll(const Dictionary& controlDict) {
    std::vector<std::unique_ptr<FunctionObject>> all;
    if (!controlDict.has("functions")) return all;
    const Dictionary fns = controlDict.subDict("functions");
    for (const std::string& name : fns.keys()) {
        all.push_back(FunctionObjectRegistry<dim>::create(fns.subDict(name), name));
    }
    fns.checkUnknownKeys();
    return all;
}

template class FunctionObject<2>;
template class FunctionObject<3>;

MPM_FAMILY_INFO("functionObjects",
                {"functions.<name>.type in system/controlDict",
                 "2. system/controlDict",
                 {{"type", "word", "-", "required", "the function object"},
                  {"writeControl", "word", "-", "timeStep", "the schedule: timeStep or runTime"},
                  {"writeInterval", "integer or scalar", "steps or s", "1 or 0",
                   "every N steps (timeStep), or every interval (runTime; 0: every step)"}}});
MPM_FAMILY_DIMS(FunctionObjectRegistry, "functionObjects");

} // namespace mpm
