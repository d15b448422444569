// SPDX-License-Identifier: GPL-3.0-or-later
// MpmSimulation: what a run writes: time directories, function objects, the failure dump and the
// closing report.
#include "solver/MpmSimulation.hpp"

#include "core/Log.hpp"
#include "core/Parallel.hpp"
#include "io/ParticleIO.hpp"
#include "io/PvtuFile.hpp"
#include "io/SeedingRecord.hpp"
#include "solver/FailureReport.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace mpm {

template <int dim> void MpmSimulation<dim>::executeFunctions() {
    if (functions_.empty()) return;
    auto timer = timer_(PhaseTimer::Functions);
    const State<dim> s = state(); // once: its reductions are collective
    for (auto& f : functions_)
        f->execute(s, *time_);
}

template <int dim> void MpmSimulation<dim>::write() {
    if (options_.dryRun) return;
    auto timer = timer_(PhaseTimer::IO);
    std::vector<std::string> files{"particles.vtu"};
    if (!bodies_.empty()) files.push_back("rigidBodies.vtp");
    const io::PointCloud cloud = io::toPointCloud(particles_);
    const std::vector<std::string> purged = writer_.write(
        *time_,
        [this, &cloud](const std::filesystem::path& dir) {
            io::writeVtu(dir / "particles.vtu", cloud);
            if (subdomain_) subdomain_->writeTime(dir); // a rebalanced decomposition
            if (!acceleration_->isConstant())
                io::writeScalarFile(dir / "uniform" / "accelerationWork", "work",
                                    accelerationWork_);
            if (!bodies_.empty()) bodies_.write(dir);
            if (!seedingRecord_.empty()) {
                std::filesystem::create_directories(dir / "uniform");
                io::writeTextAtomic(dir / "uniform" / "seeding", seedingRecord_);
            }
            if (wallContactIsState()) {
                // Files number the nodes x fastest (Grid::fileIndex), whatever the storage.
                std::vector<std::pair<Index, int>> contact = bc_.wallContact();
                for (auto& [node, axes] : contact)
                    node = grid_.fileIndex(node);
                std::sort(contact.begin(), contact.end());
                io::writeIndexFlags(dir / "uniform" / "wallContact", "nodes", contact);
            }
        },
        files);
    seedingRecord_.clear(); // the seeded time only
    if (!comm_.parallel()) return;
    // A parallel run: rank r wrote processor<r>/<time>/ (its points and the restart state);
    // rank 0 writes <time>/particles.pvtu, which ParaView opens as one data set of all pieces,
    // and the bodies, once every piece is there.
    comm_.barrier();
    if (!rootWriter_) return;
    files[0] = "particles.pvtu";
    const std::string name = time_->name();
    std::vector<std::string> pieces;
    for (int r = 0; r < comm_.size(); ++r)
        pieces.push_back("../processor" + std::to_string(r) + "/" + name + "/particles.vtu");
    rootWriter_->write(
        *time_,
        [&](const std::filesystem::path& dir) {
            io::writePvtu(dir / "particles.pvtu", cloud, pieces);
            if (!bodies_.empty()) bodies_.write(dir);
        },
        files, &purged);
}

template <int dim>
void MpmSimulation<dim>::fail(const std::string& phase, Index particle, const std::string& what) {
    std::ostringstream os;
    os << "step " << time_->index() << " (t = " << time_->value() << " s), phase " << phase << ": "
       << describePoint(particles_, particle, comm_.size() > 1 ? comm_.rank() : -1) << what << '.';
    SolverState solver;
    if (!options_.dryRun && good_.restore(particles_, bodies_, *time_, solver)) {
        accelerationWork_ = solver.accelerationWork; // what the written time directory holds
        if (wallContactIsState()) bc_.setWallContact(solver.wallContact);
        write();
        os << "\nThe last good state (step " << time_->index() << ", t = " << time_->value()
           << " s) is written to " << time_->name() << "/.";
    }
    throw RunError(os.str());
}

template <int dim> void MpmSimulation<dim>::report(std::ostream& os) const {
    const long total = numParticles();
    timer_.report(os, total, coupling_ != nullptr, !bodies_.empty(), comm_.parallel());
    if (comm_.parallel()) {
        // Load balance and communication of the run (docs/parallel.md).
        const std::vector<double> points = comm_.gather(static_cast<double>(particles_.size()));
        const std::vector<double> comm = comm_.gather(timer_.seconds(PhaseTimer::Comm));
        const double mean = static_cast<double>(total) / comm_.size();
        const double most = *std::max_element(points.begin(), points.end());
        os << std::defaultfloat << std::setprecision(4) << "Ranks: " << comm_.size()
           << ", points per rank max/mean " << (mean > 0 ? most / mean : 1.0) << ", comm "
           << *std::max_element(comm.begin(), comm.end()) << " s (slowest rank), halo "
           << subdomain_->halo().bytesSent() / std::max<long>(timer_.steps(), 1) / 1024.0
           << " KiB per step sent by rank 0\n";
    }
    if (const Index removed = comm_.sum(removed_); removed > 0)
        os << removed << " particles left through open faces and were removed\n";
    if (splitting_ && split_ > 0) os << split_ << " particles were split in two\n";
    // Memory that follows the material: the active blocks' node fields, the particles' state.
    const double active = static_cast<double>(grid_.activeBlocks().size());
    const double nodeBytes = Grid<dim>::BytesPerNode;
    double particleBytes = 0;
    particles_.forEachField([&](const FieldInfo&, const auto& a) {
        particleBytes += sizeof(typename std::decay_t<decltype(a)>::value_type);
    });
    os << std::defaultfloat << std::setprecision(4) << "Sparse grid: " << active << " of "
       << grid_.numBlocks() << " blocks active (" << 100.0 * active / grid_.numBlocks() << " %), "
       << active * Grid<dim>::NodesPerBlock * nodeBytes / 1048576.0 << " MiB of node fields ("
       << nodeBytes << " B per node); particle state " << particleBytes
       << " B per particle, kernel stencils " << transfer_->stencilBytes() << " B per particle\n";
    const double pups = timer_.updatesPerSecond(total);
    os << std::defaultfloat << std::setprecision(4) << "Particle-updates per second: " << pups
       << " (" << pups / 1e6 << " M)\n";
}

// The members above, for both dimensions (the class itself is instantiated in MpmSimulation.cpp).
#define MPM_SIMULATION_OUTPUT(D)                                                                   \
    template void MpmSimulation<D>::executeFunctions();                                            \
    template void MpmSimulation<D>::write();                                                       \
    template void MpmSimulation<D>::fail(const std::string&, Index, const std::string&);           \
    template void MpmSimulation<D>::report(std::ostream&) const;
MPM_SIMULATION_OUTPUT(2)
MPM_SIMULATION_OUTPUT(3)
#undef MPM_SIMULATION_OUTPUT

} // namespace mpm
