// SPDX-License-Identifier: GPL-3.0-or-later
#include "solver/Application.hpp"

#include "core/BuildInfo.hpp"
#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/Memory.hpp"

#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace mpm {

Application::Application(int argc, char* argv[], std::string name, std::string summary,
                         std::vector<Option> switches, std::string footer)
    : name_(std::move(name)), summary_(std::move(summary)), footer_(std::move(footer)),
      switches_(std::move(switches)) {
    std::cout.setf(std::ios::unitbuf); // the log is followed live (tail -f log.mpmFoam)
    for (int i = 0; i < argc; ++i)
        commandLine_ += (i ? " " : "") + std::string(argv[i]);
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "-help" || a == "--help" || a == "-h") {
            help_ = true;
        } else if (a == "-case") {
            if (i + 1 >= argc) {
                badOption_ = "-case needs a directory";
                break;
            }
            caseDir_ = argv[++i];
        } else if (std::any_of(switches_.begin(), switches_.end(),
                               [&](const Option& o) { return o.first == a; })) {
            given_.push_back(a);
        } else if (std::any_of(switches_.begin(), switches_.end(), [&](const Option& o) {
                       return o.first.compare(0, a.size() + 2, a + " [") == 0;
                   })) {
            // An optional value (`-list [family]`): the next word unless it is an option.
            given_.push_back(a);
            if (i + 1 < argc && argv[i + 1][0] != '-') values_.emplace_back(a, argv[++i]);
        } else if (std::any_of(switches_.begin(), switches_.end(), [&](const Option& o) {
                       return o.first.compare(0, a.size() + 2, a + " <") == 0;
                   })) {
            if (i + 1 >= argc) {
                badOption_ = a + " needs a value";
                break;
            }
            given_.push_back(a);
            values_.emplace_back(a, argv[++i]);
        } else {
            badOption_ = "Invalid option: " + a;
            break;
        }
    }
}

bool Application::has(const std::string& option) const {
    return std::find(given_.begin(), given_.end(), option) != given_.end();
}

std::string Application::value(const std::string& option) const {
    for (const auto& [o, v] : values_)
        if (o == option) return v;
    return {};
}

void Application::usage(std::ostream& os) const {
    os << "\nUsage: " << name_ << " [OPTIONS]\n\n" << summary_ << "\n\noptions:\n";
    std::vector<Option> all = switches_;
    all.emplace_back("-case <dir>", "case directory (default: the current directory)");
    all.emplace_back("-help", "print this usage and exit");
    std::sort(all.begin(), all.end());
    for (const auto& [o, d] : all)
        os << "  " << std::left << std::setw(22) << o << d << '\n';
    os << '\n' << footer_ << (footer_.empty() ? "" : "\n\n");
}

int Application::run(const std::function<void()>& body) const {
    if (help_) {
        usage(std::cout);
        return 0;
    }
    if (!badOption_.empty()) {
        std::cerr << "\n--> MPMFOAM FATAL ERROR: " << badOption_ << '\n';
        usage(std::cerr);
        return 1;
    }
    char host[256] = "unknown";
    gethostname(host, sizeof host - 1);
    const std::time_t now = std::time(nullptr);
    char date[64];
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M:%S", std::localtime(&now));
    log() << "/*---------------------------------------------------------------------------*\\\n"
          << "  mpmFoam " << buildVersion << ": material point method for granular media\n"
          << "\\*---------------------------------------------------------------------------*/\n"
          << "Build   : " << buildRevision << '\n'
          << "Exec    : " << commandLine_ << '\n'
          << "Date    : " << date << '\n'
          << "Host    : " << host << '\n'
          << "PID     : " << getpid() << '\n'
          << "Case    : " << caseDir_ << '\n'
          << "Threads : " << omp_get_max_threads() << "\n\n";
    return reportingErrors([&] {
        body();
        return 0;
    });
}

void reportPeakMemory(std::ostream& os) {
    const PeakMemory peak = peakResident();
    if (peak.bytes < 0) {
        os << "Peak memory: unknown (neither /proc/self/status nor getrusage)\n";
        return;
    }
    std::ostringstream line; // leaves the log's format flags alone
    line << std::fixed << std::setprecision(1) << "Peak memory: " << peak.bytes / 1048576.0
         << " MiB (" << peak.source << ")\n";
    os << line.str();
}

ProgressMeter::ProgressMeter(const Time& time)
    : time_(time), wall0_(omp_get_wtime()), lastWall_(wall0_), lastIndex_(time.index()) {}

void ProgressMeter::print() {
    const double now = omp_get_wtime();
    const double rate = (time_.index() - lastIndex_) / std::max(now - lastWall_, 1e-9);
    const double simRate = (time_.value() - time_.startValue()) / std::max(now - wall0_, 1e-9);
    const double eta = simRate > 0 ? (time_.endTime() - time_.value()) / simRate : 0.0;
    const long s = static_cast<long>(eta);
    log() << "Time = " << std::setprecision(time_.writePrecision()) << time_.value()
          << "  deltaT = " << time_.deltaT() << "  steps/s = " << std::setprecision(4) << rate
          << "  ETA = " << s / 3600 << 'h' << std::setw(2) << std::setfill('0') << (s / 60) % 60
          << 'm' << std::setw(2) << s % 60 << 's' << std::setfill(' ') << "  wrote " << time_.name()
          << "/\n";
    lastWall_ = now;
    lastIndex_ = time_.index();
}

} // namespace mpm
