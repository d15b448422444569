// SPDX-License-Identifier: GPL-3.0-or-later
#include "solver/MpmSimulation.hpp"

#include "TestSupport.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

namespace {

using namespace mpm;

void writeFile(const std::filesystem::path& file, const std::string& text) {
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file) << text;
}

/// A case without external force: an elastic block in the middle of a large box (no wall near
/// it) with a non-uniform velocity (an axial mode), so that internal forces act in the step.
void writeCase(const std::filesystem::path& dir, int dim, const std::string& schemes) {
    const bool d3 = dim == 3;
    writeFile(dir / "system/controlDict", "endTime: 1\ndeltaT: 1e-4\nwriteInterval: 1\n");
    writeFile(dir / "system/mpmSchemes", schemes);
    writeFile(dir / "constant/grid",
              std::string("dimension: ") + (d3 ? "3" : "2") + "\ncellSize: 0.05\nbounds: " +
                  (d3 ? "{min: [0, 0, 0], max: [1, 1, 1]}" : "{min: [0, 0], max: [1, 1]}") + "\n");
    writeFile(dir / "constant/materials",
              "block: {type: henckyElastic, density: 1000, E: 1.0e6, nu: 0.3}\n");
    writeFile(
        dir / "constant/particles",
        std::string("block:\n  material: block\n  region: {type: box, min: ") +
            (d3 ? "[0.3, 0.35, 0.4], max: [0.7, 0.65, 0.6]}" : "[0.3, 0.35], max: [0.7, 0.65]}") +
            "\n  velocity: {type: axialMode, amplitude: 0.5, direction: " +
            (d3 ? "[1, 0.5, 0.2]" : "[1, 0.5]") +
            ", origin: " + (d3 ? "[0.3, 0.35, 0.4]" : "[0.3, 0.35]") + ", length: 0.4, mode: 2}\n");
}

template <int dim> void expectConserved(const std::string& schemes) {
    SCOPED_TRACE(schemes);
    test::TempDir tmp;
    writeCase(tmp.path(), dim, schemes);
    const Case cs(tmp.path());
    Time time(cs);
    const auto owner = Simulation::create(cs, RunOptions{true, true});
    auto& sim = dynamic_cast<MpmSimulation<dim>&>(*owner);
    sim.start(time);
    auto totals = [&](double& mass, Vec<dim>& momentum) {
        const auto& p = sim.particles();
        mass = 0;
        momentum.setZero();
        for (std::size_t i = 0; i < p.size(); ++i) {
            mass += p.mass[i];
            momentum += p.mass[i] * p.v[i];
        }
    };
    double m0, m1;
    Vec<dim> p0, p1;
    totals(m0, p0);
    ASSERT_GT(p0.norm(), 0.0);
    for (int k = 0; k < 3; ++k) {
        time.advance(sim.stableDeltaT());
        sim.step(time.deltaT());
    }
    totals(m1, p1);
    EXPECT_EQ(m1, m0);
    EXPECT_LT((p1 - p0).norm(), 1e-12 * p0.norm()) << p0.transpose() << " → " << p1.transpose();
    // The step did something: stresses are not zero (USF once left them so).
    double stress = 0;
    for (const auto& s : sim.particles().stress)
        stress = std::max(stress, s.norm());
    EXPECT_GT(stress, 0.0);
}

TEST(MpmSimulation, StepsConserveMassAndMomentumWithoutExternalForce) {
    for (const char* order : {"USL", "USF", "MUSL"})
        for (const char* scheme :
             {"kernel: gimp\ntransfer: {type: flip, ratio: 0.99}\n",
              "kernel: quadraticBSpline\ntransfer: apic\n", "kernel: linear\ntransfer: pic\n"}) {
            const std::string s = std::string(scheme) + "stressUpdate: " + order + "\n";
            expectConserved<2>(s);
            expectConserved<3>(s);
        }
}

std::string readText(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

/// An elastic block sliding fast along a slip floor, pressed onto it, under a g that ramps up
/// (time-varying: its work is restart state), USF (the walls' contact is restart state).
void writeFallingBlock(const std::filesystem::path& dir) {
    writeFile(dir / "system/controlDict", "endTime: 1\ndeltaT: 1e-4\nwriteInterval: 1\n");
    writeFile(dir / "system/mpmSchemes", "kernel: linear\ntransfer: {type: flip, ratio: 1.0}\n"
                                         "stressUpdate: USF\n");
    writeFile(dir / "constant/grid", "dimension: 2\ncellSize: 0.05\nbounds: {min: [0, 0], "
                                     "max: [1, 1]}\nboundary: {yMin: slip}\n");
    writeFile(dir / "constant/g", "type: ramp\nvalue: [0, -9.81]\nduration: 0.01\n");
    writeFile(dir / "constant/materials",
              "block: {type: henckyElastic, density: 1000, E: 1.0e6, nu: 0.3}\n");
    writeFile(dir / "constant/particles", "block:\n  material: block\n  region: {type: box, "
                                          "min: [0.3, 0.0], max: [0.7, 0.3]}\n"
                                          "  velocity: [60, -1]\n");
}

TEST(MpmSimulation, FailureWritesTheLastGoodStateWithItsOwnWorkAndWallContact) {
    test::TempDir tmp;
    writeFallingBlock(tmp.path());
    const Case cs(tmp.path());
    Time time(cs);
    const auto owner = Simulation::create(cs, RunOptions{false, true});
    auto& sim = dynamic_cast<MpmSimulation<2>&>(*owner);
    sim.start(time);
    for (int k = 0; k < 20; ++k) { // the last good state is kept every 20th step
        time.advance(sim.stableDeltaT());
        sim.step(time.deltaT());
    }
    sim.write(); // what the good state's time directory holds written at that time
    const std::filesystem::path good = tmp.path() / time.name() / "uniform";
    const std::string work = readText(good / "accelerationWork");
    const std::string contact = readText(good / "wallContact");
    ASSERT_EQ(contact.find("nodes: []"), std::string::npos) << "the block rests on the floor";
    for (int k = 0; k < 10; ++k) { // g changes, and the block slides 6 cm = 1.2 h on
        time.advance(sim.stableDeltaT());
        sim.step(time.deltaT());
    }
    sim.write();
    const std::filesystem::path later = tmp.path() / time.name() / "uniform";
    ASSERT_NE(readText(later / "accelerationWork"), work);
    ASSERT_NE(readText(later / "wallContact"), contact);
    time.advance(sim.stableDeltaT());
    std::filesystem::remove_all(good.parent_path());
    EXPECT_THROW(sim.step(10.0), RunError); // moves many cells: stops, writes the good state
    EXPECT_EQ(readText(good / "accelerationWork"), work);
    EXPECT_EQ(readText(good / "wallContact"), contact);
}

TEST(MpmSimulation, MovedMoreThanOneCellTestsTheDisplacementNotTheFlipVelocity) {
    // Two coincident point sets moving at ±V: the grid velocity is 0, so with FLIP the points
    // keep |v| = V but do not move. A step with V Δt = 4 h must not stop; a set moving at V
    // must.
    const auto run = [](bool opposed) {
        test::TempDir tmp;
        writeFile(tmp.path() / "system/controlDict", "endTime: 1\ndeltaT: 1e-4\n"
                                                     "writeInterval: 1\n");
        writeFile(tmp.path() / "system/mpmSchemes",
                  "kernel: linear\ntransfer: {type: flip, ratio: 1.0}\nstressUpdate: USL\n");
        writeFile(tmp.path() / "constant/grid",
                  "dimension: 2\ncellSize: 0.05\nbounds: {min: [0, 0], max: [1, 1]}\n");
        writeFile(tmp.path() / "constant/materials",
                  "block: {type: henckyElastic, density: 1000, E: 1.0e6, nu: 0.3}\n");
        const std::string region = "  material: block\n  region: {type: box, min: [0.4, 0.4], "
                                   "max: [0.6, 0.6]}\n";
        writeFile(tmp.path() / "constant/particles",
                  "right:\n" + region + "  velocity: [2, 0]\n" +
                      (opposed ? "left:\n" + region + "  velocity: [-2, 0]\n" : std::string()));
        const Case cs(tmp.path());
        Time time(cs);
        const auto owner = Simulation::create(cs, RunOptions{true, true});
        auto& sim = dynamic_cast<MpmSimulation<2>&>(*owner);
        sim.start(time);
        time.advance(sim.stableDeltaT());
        try {
            sim.step(0.1); // |v| Δt = 0.2 m = 4 h
        } catch (const RunError& e) {
            return std::string(e.what());
        }
        double moved = 0;
        for (const auto& x : sim.particles().x)
            moved = std::max(moved, std::fabs(x[0] - 0.5));
        EXPECT_LT(moved, 0.1 + 1e-9); // no point left the block's span
        return std::string();
    };
    EXPECT_EQ(run(true), "");
    const std::string stopped = run(false);
    EXPECT_NE(stopped.find("moved more than one cell"), std::string::npos) << stopped;
    EXPECT_NE(stopped.find("particle "), std::string::npos) << stopped;
}

} // namespace
