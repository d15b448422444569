// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/TimeDirectory.hpp"

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "io/ParticleIO.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>

namespace mpm::io {

namespace fs = std::filesystem;

TimeDirectoryWriter::TimeDirectoryWriter(const Case& cs, std::vector<std::string> indices)
    : case_(cs), names_(std::move(indices)), pvd_(names_.size()) {}

std::vector<std::string>
TimeDirectoryWriter::write(Time& time, const std::function<void(const fs::path&)>& fill,
                           const std::vector<std::string>& files,
                           const std::vector<std::string>* purge) {
    const std::string name = time.name();
    const fs::path dir = case_.path(name);
    const fs::path tmp = case_.path("." + name + ".writing");
    fs::remove_all(tmp);
    fs::create_directories(tmp);
    fill(tmp);
    time.writeTimeDict(tmp);
    fs::remove_all(dir);
    fs::rename(tmp, dir);

    for (std::size_t k = 0; k < names_.size(); ++k) {
        if (!pvd_[k])
            pvd_[k] = std::make_unique<PvdIndex>(case_.path(names_[k] + ".pvd"), time.value());
        pvd_[k]->add(time.value(), name + "/" + files[k]);
    }
    const std::vector<std::string> old = purge ? *purge : time.wrote();
    for (const std::string& o : old) {
        fs::remove_all(case_.path(o));
        for (std::size_t k = 0; k < names_.size(); ++k)
            pvd_[k]->remove(o + "/" + files[k]);
    }
    return old;
}

std::string restartDirectory(const Case& cs, const Time& time) {
    const auto dirs = cs.timeDirectories();
    std::string from;
    if (time.startFrom() == "latestTime" && !dirs.empty()) from = dirs.back().second;
    if (time.startFrom() == "firstTime" && !dirs.empty()) from = dirs.front().second;
    if (time.startFrom() == "startTime") {
        for (const auto& [t, n] : dirs)
            if (std::fabs(t - time.startTime()) <= 1e-12 * std::max(1.0, t)) from = n;
        if (from.empty() && time.startTime() != 0.0)
            time.dict().error("startTime", "no time directory " + timeName(time.startTime(), 6) +
                                               " with particles.vtu to start from");
    }
    return from;
}

namespace {

/// Strings joined by '\0' (time names and messages hold none), and back.
std::vector<char> pack(const std::vector<std::string>& items) {
    std::vector<char> out;
    for (const std::string& s : items) {
        out.insert(out.end(), s.begin(), s.end());
        out.push_back('\0');
    }
    return out;
}

std::vector<std::string> unpack(const std::vector<char>& bytes) {
    std::vector<std::string> items;
    std::string cur;
    for (const char c : bytes) {
        if (c != '\0') {
            cur += c;
        } else {
            items.push_back(cur);
            cur.clear();
        }
    }
    return items;
}

/// "processor0, processor2" (the first 8, then how many more).
std::string processorList(const std::vector<int>& ranks) {
    std::string out;
    for (std::size_t k = 0; k < ranks.size() && k < 8; ++k)
        out += (k ? ", processor" : "processor") + std::to_string(ranks[k]);
    if (ranks.size() > 8) out += " and " + std::to_string(ranks.size() - 8) + " more";
    return out;
}

/// Rank 0's decision from every rank's {failure, chosen directory, complete times…}:
/// {"ok", directory, log line} or {"error", message}.
std::vector<std::string> agree(const std::vector<std::vector<std::string>>& ranks,
                               const std::string& startFrom) {
    const int n = static_cast<int>(ranks.size());
    for (int r = 0; r < n; ++r)
        if (!ranks[r][0].empty())
            return {"error", "processor" + std::to_string(r) + ": " + ranks[r][0]};
    const auto value = [](const std::string& name) { return std::strtod(name.c_str(), nullptr); };
    const auto listTimes = [&] {
        std::string out;
        for (int r = 0; r < n && r < 8; ++r) {
            out += (r ? "; processor" : "processor") + std::to_string(r) + ": ";
            const std::size_t k = ranks[r].size();
            out += k == 2 ? "none" : k > 5 ? "…, " : "";
            for (std::size_t i = k > 5 ? k - 3 : 2; i < k; ++i)
                out += ranks[r][i] + (i + 1 < k ? ", " : "");
        }
        return out + (n > 8 ? "; …" : "");
    };
    if (startFrom != "latestTime") {
        for (int r = 1; r < n; ++r)
            if (ranks[r][1] != ranks[0][1])
                return {"error", "startFrom " + startFrom + ": the processor folders start from " +
                                     "different times (processor0: '" + ranks[0][1] +
                                     "', processor" + std::to_string(r) + ": '" + ranks[r][1] +
                                     "'; times held: " + listTimes() + ")"};
        return {"ok", ranks[0][1], ""};
    }
    // Times every processor holds complete; the latest of them.
    std::map<std::string, int> held;
    for (const auto& rank : ranks)
        for (std::size_t i = 2; i < rank.size(); ++i)
            ++held[rank[i]];
    if (held.empty()) return {"ok", "", ""}; // a fresh start
    std::string from;
    for (const auto& [name, count] : held)
        if (count == n && (from.empty() || value(name) > value(from))) from = name;
    if (from.empty())
        return {"error", "no time directory is complete in every processor folder (" + listTimes() +
                             "): there is no common time to resume from; run decomposePar "
                             "-force to start again"};
    // Newer times that only some processors hold, by time.
    std::map<double, std::pair<std::string, std::vector<int>>> newer;
    for (int r = 0; r < n; ++r)
        for (std::size_t i = 2; i < ranks[r].size(); ++i)
            if (value(ranks[r][i]) > value(from)) {
                auto& entry = newer[value(ranks[r][i])];
                entry.first = ranks[r][i];
                entry.second.push_back(r);
            }
    std::string line;
    if (!newer.empty()) {
        line = "Resuming from time " + from +
               ", the latest time complete in every processor folder; ignoring the newer "
               "incomplete time" +
               (newer.size() > 1 ? "s " : " ");
        std::size_t k = 0;
        for (const auto& [t, entry] : newer)
            line +=
                (k++ ? ", " : "") + entry.first + " (only in " + processorList(entry.second) + ")";
        line += ": a run stopped while writing; overwritten as the run proceeds\n";
    }
    return {"ok", from, line};
}

} // namespace

std::string restartDirectory(const Case& cs, const Time& time, const Comm& comm) {
    if (!comm.parallel()) return restartDirectory(cs, time);
    // Every rank's choice and complete times go to rank 0, which decides for all: a failure
    // stops every rank alike.
    std::vector<std::string> mine(2);
    try {
        mine[1] = restartDirectory(cs, time);
    } catch (const InputError& e) {
        mine[0] = e.what();
    }
    for (const auto& [t, name] : cs.timeDirectories())
        mine.push_back(name);
    std::vector<std::vector<char>> send(static_cast<std::size_t>(comm.size()));
    send[0] = pack(mine);
    const std::vector<std::vector<char>> recv = comm.exchange(send);
    std::vector<std::string> decision;
    if (comm.master()) {
        std::vector<std::vector<std::string>> ranks;
        for (const std::vector<char>& bytes : recv)
            ranks.push_back(unpack(bytes));
        decision = agree(ranks, time.startFrom());
    }
    const std::vector<char> packed = pack(decision);
    const std::string all = comm.broadcast(std::string(packed.begin(), packed.end()));
    decision = unpack(std::vector<char>(all.begin(), all.end()));
    if (decision.empty() || decision[0] != "ok")
        throw InputError(cs.globalRoot().string(), 0, "",
                         decision.size() > 1 ? decision[1] : "no restart time agreed");
    if (!decision[2].empty()) log() << decision[2];
    return decision[1];
}

template <int dim>
void readParticles(const Case& cs, const std::string& timeDir, Particles<dim>& p,
                   std::size_t numMaterials) {
    const std::string file = cs.displayName(timeDir + "/particles.vtu"); // processorN/… too
    PointCloud cloud;
    try {
        cloud = readVtu(cs.path(timeDir + "/particles.vtu"));
    } catch (const std::exception& e) {
        throw InputError(file, 0, "", e.what());
    }
    fromPointCloud(cloud, p, file);
    for (const int m : p.material)
        if (m < 0 || m >= static_cast<int>(numMaterials))
            throw InputError(file, 0, "material",
                             "material index " + std::to_string(m) +
                                 " is not defined in constant/materials");
}

template void readParticles(const Case&, const std::string&, Particles<2>&, std::size_t);
template void readParticles(const Case&, const std::string&, Particles<3>&, std::size_t);

} // namespace mpm::io
