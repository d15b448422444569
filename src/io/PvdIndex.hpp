// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace mpm::io {

/// ParaView's time-series index (`particles.pvd`): a `<Collection>` of
/// `<DataSet timestep="t" group="" part="0" file="<time>/particles.vtu"/>`, paths relative to
/// the index, timesteps written with "%.17g". Rewritten atomically after every change.
class PvdIndex {
public:
    /// `file` is the index (e.g. case/particles.pvd). Existing entries are loaded when present
    /// (a restarted run appends to them), dropping those with time > `keepUpTo`.
    explicit PvdIndex(std::filesystem::path file, double keepUpTo = 1e300);

    /// Add (or replace) the entry for `time`, pointing at `relativeFile`, and rewrite the index.
    void add(double time, const std::string& relativeFile);
    /// Remove every entry whose file is `relativeFile` or lies in directory `relativeFile` (a time
    /// directory name such as "0.05"), and rewrite the index when something was removed.
    void remove(const std::string& relativeFile);

    struct Entry {
        double time;
        std::string file;
    };
    const std::vector<Entry>& entries() const { return entries_; }

private:
    void write() const;
    std::filesystem::path file_;
    std::vector<Entry> entries_;
};

} // namespace mpm::io
