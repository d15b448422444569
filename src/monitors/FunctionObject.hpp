// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Case.hpp"
#include "case/Dictionary.hpp"
#include "case/Registry.hpp"
#include "case/Time.hpp"
#include "solver/State.hpp"

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

namespace mpm {

/// A run-time monitor from controlDict `functions: {<name>: {type: …}}` (OpenFOAM's
/// functionObject). It writes `postProcessing/<name>/<startTime>/<name>.dat`: a `#` header
/// (`# <name>`, any headerLines(), `# time <columns>`), then one row per execution, time
/// first. `writeControl: timeStep` with `writeInterval: N` (default 1) executes it every N
/// steps; `runTime` every writeInterval seconds.
template <int dim> class FunctionObject {
public:
    FunctionObject(const Dictionary& dict, std::string name);
    virtual ~FunctionObject() = default;

    const std::string& name() const { return name_; }
    /// Why this function object cannot be evaluated from a written time (mpmFoam -postProcess):
    /// the data of the time step it reads ("needs the time step's contact search"); empty when
    /// its values follow from the state a time directory holds.
    virtual std::string needsStep() const { return {}; }

    /// Check the entries against the simulation (named bodies exist, …) and record initial
    /// values; called for every function object before any of them writes, and in -dry-run.
    void prepare(const State<dim>& s, const Time& time) { initialise(s, time); }
    /// Open the output file (a restarted run opens a new <startTime> folder) and start the
    /// schedule. `write` false (ranks other than 0 of a parallel run): the schedule only; the
    /// values are computed on every rank (their reductions are collective), written by rank 0.
    void open(const Case& cs, const Time& time, bool write = true);
    /// The file open() writes at `time`: `postProcessing/<name>/<time, 6 digits>/<name>.dat`.
    std::filesystem::path file(const Case& cs, const Time& time) const;
    /// Sample every step (sample()) and write a row if the schedule says so.
    void execute(const State<dim>& s, const Time& time);
    /// Execute now (the initial state).
    void executeNow(const State<dim>& s, const Time& time);

    /// All function objects of controlDict.
    static std::vector<std::unique_ptr<FunctionObject>> createAll(const Dictionary& controlDict);

protected:
    /// This function object's entry in controlDict (for errors located at file:line).
    const Dictionary& dict() const { return dict_; }
    /// Called every step before a possible write (for time averages); default: nothing.
    virtual void sample(const State<dim>&, const Time&) {}
    /// Called once when the output opens (e.g. to record the initial state).
    virtual void initialise(const State<dim>&, const Time&) {}
    /// Extra `#` header lines between the name and the column line (text after "# ");
    /// default: none.
    virtual std::vector<std::string> headerLines(const State<dim>&) const { return {}; }
    /// Column names after "time".
    virtual std::vector<std::string> columns(const State<dim>& s) const = 0;
    /// One row of values matching columns().
    virtual std::vector<double> values(const State<dim>& s) const = 0;

private:
    Dictionary dict_;
    std::string name_;
    bool byTime_ = false;
    double interval_ = 1;
    long lastIndex_ = -1;
    std::ofstream out_;
    bool headerDone_ = false;
    int precision_ = 6;
};

template <int dim> using FunctionObjectRegistry = Registry<FunctionObject<dim>, const std::string&>;

} // namespace mpm
