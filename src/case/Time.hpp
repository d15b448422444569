// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Case.hpp"

#include <deque>
#include <filesystem>
#include <functional>
#include <string>

namespace mpm {

/// Run control from system/controlDict (OpenFOAM's Time): the time step, the write schedule,
/// stop requests (stopAt, signals, a `stop` file) and re-reading a modified controlDict.
class Time {
public:
    enum class StopAt { EndTime, WriteNow, NoWriteNow, NextWrite };
    enum class WriteControl { TimeStep, RunTime, AdjustableRunTime };

    explicit Time(const Case& cs);

    /// Set the state a run starts from (a fresh start or a restart's uniform/time).
    void setStart(double value, long index, double deltaT0);
    /// Read `<case>/<name>/uniform/time` (restart).
    void readTimeDict(const std::string& name);

    /// True while the run goes on; checks endTime and stop requests (call once per step).
    bool run();
    /// True when the current time has reached endTime (within run()'s tolerance: 1e-9 Δt with
    /// adjustTimeStep, half a fixed step otherwise), so run() takes no step.
    bool endReached() const;
    /// True when the start state was read from a time directory (readTimeDict), not seeded.
    bool restarted() const { return restarted_; }
    /// Choose Δt from the stable step `stableDeltaT` (used when adjustTimeStep is on) and the
    /// write schedule, then advance the time by it.
    void advance(double stableDeltaT);
    /// True if the step just taken ends at a write time (or a write was requested).
    bool writeTime() const { return writeTime_; }
    /// After the loop: true if a stop request asks for the current state to be written and it
    /// has not been written yet.
    bool writeAtEnd() const { return stopWrite_ && lastWrittenStep_ != index_; }
    /// Record a write of the current time; returns the time directories to purge.
    std::vector<std::string> wrote();
    /// Write `<case>/<name>/uniform/time`.
    void writeTimeDict(const std::filesystem::path& dir) const;

    double value() const { return value_; }
    double deltaT() const { return deltaT_; }
    long index() const { return index_; }
    std::string name() const;
    double endTime() const { return endTime_; }
    double startValue() const { return startValue_; }
    bool adjustTimeStep() const { return adjust_; }
    double maxCo() const { return maxCo_; }
    double fixedDeltaT() const { return fixedDeltaT_; }
    int writePrecision() const { return writePrecision_; }
    const std::string& startFrom() const { return startFrom_; }
    double startTime() const { return startTime_; }
    /// "Fixed deltaT above the stable limit" is an error unless the case asks for a warning.
    bool allowUnstableDeltaT() const { return allowUnstable_; }
    /// With a fixed Δt (adjustTimeStep: no), refuse a deltaT above the stable step `critical`
    /// [s] (an InputError on deltaT naming `limit`, the formula and its values) unless
    /// allowUnstableDeltaT, which only warns.
    void checkFixedDeltaT(double critical, const std::string& limit) const;
    /// Line of `key` in system/controlDict, for messages.
    const Dictionary& dict() const { return dict_; }
    /// True after stop was requested (signal, stop file, stopAt writeNow/noWriteNow).
    bool stopping() const { return stopNow_; }

    /// A parallel run: `anyRank(x)` is true when x is true on any rank (Comm::any). Stop and write
    /// requests and a changed controlDict then take effect on every rank at the same step.
    void setAgreement(std::function<bool(bool)> anyRank) { agree_ = std::move(anyRank); }

    /// Install SIGUSR1 (write now), SIGUSR2 and SIGTERM (write and stop) handlers.
    static void installSignalHandlers();

private:
    void read(const Dictionary& d);
    void pollRequests();
    void applyStopAt();
    long writeIndexOf(double t) const;

    const Case& case_;
    Dictionary dict_;
    std::function<bool(bool)> agree_ = [](bool x) { return x; };
    std::filesystem::file_time_type dictStamp_;

    std::string startFrom_ = "latestTime";
    double startTime_ = 0;
    StopAt stopAt_ = StopAt::EndTime;
    double endTime_ = 0;
    double fixedDeltaT_ = 0;
    bool adjust_ = false;
    double maxCo_ = 0.5;
    double maxDeltaT_ = 1e300;
    WriteControl writeControl_ = WriteControl::TimeStep;
    double writeInterval_ = 1;
    int purgeWrite_ = 0;
    int writePrecision_ = 6;
    int timePrecision_ = 6;
    bool runTimeModifiable_ = true;
    bool allowUnstable_ = false;

    double value_ = 0, deltaT_ = 0, deltaT0_ = 0, startValue_ = 0;
    long index_ = 0, startIndex_ = 0;
    long lastWriteIndex_ = 0;
    bool writeTime_ = false;
    bool stopNow_ = false;
    bool stopWrite_ = false;
    bool stopAtNextWrite_ = false;
    bool writeNowPending_ = false;
    long lastWrittenStep_ = -1;
    bool restarted_ = false;
    double lastWrittenValue_ = -1e300;
    std::string lastName_;
    std::deque<std::string> written_;
};

} // namespace mpm
