// SPDX-License-Identifier: GPL-3.0-or-later
#include "case/Time.hpp"

#include "core/Log.hpp"

#include <cmath>
#include <csignal>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace mpm {

namespace fs = std::filesystem;

namespace {
fs::path controlDictPath(const Case& cs) {
    const fs::path p = cs.globalRoot() / "system/controlDict";
    return fs::exists(p) ? p : fs::path(p.string() + ".yaml");
}

volatile std::sig_atomic_t gWriteNow = 0;
volatile std::sig_atomic_t gStopNow = 0;
extern "C" void onWriteNow(int) {
    gWriteNow = 1;
}
extern "C" void onStopNow(int) {
    gStopNow = 1;
}
} // namespace

void Time::installSignalHandlers() {
    std::signal(SIGUSR1, onWriteNow);
    std::signal(SIGUSR2, onStopNow);
    std::signal(SIGTERM, onStopNow);
}

Time::Time(const Case& cs) : case_(cs), dict_(cs.read("system/controlDict")) {
    read(dict_);
    std::error_code ec;
    dictStamp_ = fs::last_write_time(controlDictPath(cs), ec);
    deltaT_ = fixedDeltaT_;
    applyStopAt();
}

void Time::read(const Dictionary& d) {
    d.getStringOr("application", "mpmFoam");
    startFrom_ = d.getWordOr("startFrom", "latestTime", {"firstTime", "startTime", "latestTime"});
    startTime_ = d.getScalarOr("startTime", 0.0, Bounds::nonNegative());
    const std::string stop =
        d.getWordOr("stopAt", "endTime", {"endTime", "writeNow", "noWriteNow", "nextWrite"});
    stopAt_ = stop == "endTime"      ? StopAt::EndTime
              : stop == "writeNow"   ? StopAt::WriteNow
              : stop == "noWriteNow" ? StopAt::NoWriteNow
                                     : StopAt::NextWrite;
    endTime_ = d.getScalar("endTime", Bounds::nonNegative());
    fixedDeltaT_ = d.getScalar("deltaT", Bounds::positive());
    adjust_ = d.getBoolOr("adjustTimeStep", false);
    maxCo_ = d.getScalarOr("maxCo", 0.5, {0.0, 1.0, false, true});
    maxDeltaT_ = d.getScalarOr("maxDeltaT", 1e300, Bounds::positive());
    const std::string wc =
        d.getWordOr("writeControl", "timeStep", {"timeStep", "runTime", "adjustableRunTime"});
    writeControl_ = wc == "timeStep"  ? WriteControl::TimeStep
                    : wc == "runTime" ? WriteControl::RunTime
                                      : WriteControl::AdjustableRunTime;
    if (writeControl_ == WriteControl::TimeStep)
        writeInterval_ = d.getInt("writeInterval", Bounds::closed(1, 2e9));
    else
        writeInterval_ = d.getScalar("writeInterval", Bounds::positive());
    purgeWrite_ = d.getIntOr("purgeWrite", 0, Bounds::closed(0, 1e9));
    writePrecision_ = d.getIntOr("writePrecision", 6, Bounds::closed(1, 17));
    timePrecision_ = d.getIntOr("timePrecision", 6, Bounds::closed(1, 17));
    runTimeModifiable_ = d.getBoolOr("runTimeModifiable", true);
    allowUnstable_ = d.getBoolOr("allowUnstableDeltaT", false);
    d.has("functions");
    d.checkUnknownKeys();
}

void Time::setStart(double value, long index, double deltaT0) {
    value_ = startValue_ = value;
    index_ = startIndex_ = index;
    lastWrittenStep_ = index;
    lastWrittenValue_ = value;
    deltaT_ = deltaT0 > 0 ? deltaT0 : fixedDeltaT_;
    deltaT0_ = deltaT_;
    lastWriteIndex_ = writeIndexOf(value);
    lastName_ = name();
}

void Time::readTimeDict(const std::string& dirName) {
    const Dictionary d = case_.read(dirName + "/uniform/time");
    const double value = d.getScalar("value");
    const long index = d.getInt("index", Bounds::nonNegative());
    const double dt = d.getScalar("deltaT", Bounds::positive());
    d.getStringOr("name", dirName);
    d.getScalarOr("deltaT0", dt);
    d.checkUnknownKeys();
    setStart(value, index, dt);
    lastName_ = dirName;
    restarted_ = true;
}

void Time::writeTimeDict(const fs::path& dir) const {
    fs::create_directories(dir / "uniform");
    std::ofstream os(dir / "uniform" / "time");
    os << std::setprecision(17) << "value: " << value_ << "\nname: \"" << name()
       << "\"\nindex: " << index_ << "\ndeltaT: " << deltaT_ << "\ndeltaT0: " << deltaT0_ << "\n";
    if (!os) throw RunError("cannot write " + (dir / "uniform" / "time").string());
}

long Time::writeIndexOf(double t) const {
    if (writeControl_ == WriteControl::TimeStep) return index_ / static_cast<long>(writeInterval_);
    return static_cast<long>(std::floor(t / writeInterval_ + 1e-8));
}

std::string Time::name() const {
    int p = timePrecision_;
    std::string n = timeName(value_, p);
    while (p < 17 && n == lastName_ && value_ != lastWrittenValue_)
        n = timeName(value_, ++p);
    return n;
}

void Time::pollRequests() {
    // Each request is seen by this process; a parallel run acts on it when any rank saw it
    // (agree_), so that every rank writes and stops at the same step.
    const bool writeNow = agree_(gWriteNow != 0);
    const bool stopNow = agree_(gStopNow != 0);
    gWriteNow = gStopNow = 0;
    if (writeNow) {
        writeNowPending_ = true;
        log() << "Signal: write at the end of this step\n";
    }
    if (stopNow) {
        stopNow_ = stopWrite_ = true;
        log() << "Signal: write and stop\n";
    }
    const fs::path stopFile = case_.globalRoot() / "stop";
    std::error_code ec;
    if (agree_(fs::exists(stopFile, ec))) {
        fs::remove(stopFile, ec);
        stopNow_ = stopWrite_ = true;
        log() << "Found " << stopFile.string() << " (removed): write and stop\n";
    }
    if (runTimeModifiable_) {
        const auto stamp = fs::last_write_time(controlDictPath(case_), ec);
        if (agree_(!ec && stamp != dictStamp_)) {
            dictStamp_ = stamp;
            try {
                // Parse into a fresh Time first, so that a broken file changes nothing.
                const Time fresh(case_);
                read(fresh.dict_);
                dict_ = fresh.dict_;
                log() << "Re-read system/controlDict\n";
                if (!adjust_) deltaT_ = fixedDeltaT_;
                applyStopAt();
            } catch (const InputError& e) {
                warning() << "system/controlDict changed but cannot be read; keeping the "
                             "previous settings:\n    "
                          << e.what() << '\n';
            }
        }
    }
}

void Time::applyStopAt() {
    if (stopAt_ == StopAt::WriteNow) stopNow_ = stopWrite_ = true;
    if (stopAt_ == StopAt::NoWriteNow) stopNow_ = true;
    if (stopAt_ == StopAt::NextWrite) stopAtNextWrite_ = true;
}

bool Time::run() {
    pollRequests();
    if (stopNow_) return false;
    if (!endReached()) return true;
    stopWrite_ = true; // endTime reached (or lowered below the current time): write the end
    return false;
}

bool Time::endReached() const {
    const double tol = adjust_ ? 1e-9 * deltaT_ : 0.5 * fixedDeltaT_;
    return !(value_ < endTime_ - tol);
}

void Time::advance(double stableDeltaT) {
    deltaT0_ = deltaT_;
    double dt = fixedDeltaT_;
    if (adjust_) {
        dt = std::min({stableDeltaT, maxDeltaT_, 1.2 * deltaT0_});
        if (writeControl_ == WriteControl::AdjustableRunTime) {
            const double toWrite = (writeIndexOf(value_) + 1) * writeInterval_ - value_;
            if (toWrite > 0) dt = toWrite / std::ceil(toWrite / dt * (1.0 - 1e-12));
        }
        const double remaining = endTime_ - value_;
        if (remaining > 0 && dt > remaining * (1.0 - 1e-12)) dt = remaining;
    }
    deltaT_ = dt;
    value_ += dt;
    ++index_;
    writeTime_ = writeNowPending_;
    writeNowPending_ = false;
    const long wi = writeIndexOf(value_);
    if (wi > lastWriteIndex_) {
        writeTime_ = true;
        lastWriteIndex_ = wi;
    }
    if (value_ >= endTime_ - (adjust_ ? 1e-9 : 0.5) * dt) writeTime_ = true;
}

std::vector<std::string> Time::wrote() {
    const std::string n = name();
    lastName_ = n;
    lastWrittenStep_ = index_;
    lastWrittenValue_ = value_;
    std::vector<std::string> purge;
    if (written_.empty() || written_.back() != n) written_.push_back(n);
    if (purgeWrite_ > 0)
        while (static_cast<int>(written_.size()) > purgeWrite_) {
            purge.push_back(written_.front());
            written_.pop_front();
        }
    if (stopAtNextWrite_) stopNow_ = true;
    return purge;
}

void Time::checkFixedDeltaT(double critical, const std::string& limit) const {
    if (adjust_ || fixedDeltaT_ <= critical) return;
    std::ostringstream os;
    os << "deltaT = " << fixedDeltaT_ << " s exceeds the stable limit " << limit << " = "
       << critical << " s";
    if (!allowUnstable_)
        dict_.error("deltaT", os.str() + "; reduce deltaT, set adjustTimeStep: yes, or set "
                                         "allowUnstableDeltaT: yes to run anyway");
    warning() << os.str() << "; running anyway (allowUnstableDeltaT: yes)\n";
}

} // namespace mpm
