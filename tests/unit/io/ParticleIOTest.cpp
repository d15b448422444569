// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/ParticleIO.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

using namespace mpm;

template <int dim> Particles<dim> sample(int n) {
    Particles<dim> p;
    p.resize(n);
    for (int i = 0; i < n; ++i) {
        p.x[i] = Vec<dim>::Constant(0.1 * i);
        p.v[i] = Vec<dim>::Constant(-1.0 * i);
        p.C[i] = Mat<dim>::Constant(0.5 * i);
        p.L[i] = Mat<dim>::Constant(3.0);
        p.F[i] = Mat<dim>::Identity() * (1 + 0.01 * i);
        p.be[i] = Mat3::Identity() * (1 - 0.01 * i);
        p.stress[i] = Mat3::Constant(-10.0 * i);
        p.mass[i] = 2.0 + i;
        p.volume0[i] = 1e-3 * (1 + 0.1 * i);
        p.volume[i] = 1.1e-3 * (1 + 0.3 * i);
        p.plasticStrain[i] = 0.25 * i + 0.125;
        p.id[i] = 7 * i;
        p.material[i] = i % 2;
    }
    return p;
}

template <int dim> void roundTrip() {
    Particles<dim> p = sample<dim>(5);
    const std::size_t r = p.addScalar({"plasticStrainRate"});
    const std::size_t e = p.addTensor({"elasticStress"});
    const std::size_t f = p.addFlag({"state"});
    for (int i = 0; i < 5; ++i) {
        p.scalar(r)[i] = 1.0 / (i + 1);
        p.tensor(e)[i] = Mat3::Constant(i + 0.5);
        p.flag(f)[i] = i % 3;
    }
    const io::PointCloud cloud = io::toPointCloud(p);
    ASSERT_NE(cloud.find("plasticStrainRate"), nullptr);
    ASSERT_NE(cloud.find("elasticStress"), nullptr);
    EXPECT_EQ(cloud.find("elasticStress")->components, 9);
    EXPECT_TRUE(cloud.find("state")->isInteger());
    EXPECT_EQ(cloud.find("velocityGradient"), nullptr); // not written
    ASSERT_NE(cloud.find("pressure"), nullptr);         // derived
    EXPECT_DOUBLE_EQ(cloud.find("pressure")->f64[2], 20.0);
    if (dim == 2) {
        EXPECT_EQ(cloud.find("deformationGradient")->f64[8], 1.0);
    }

    Particles<dim> q = p.emptyLike();
    io::fromPointCloud(cloud, q, "test.vtu");
    EXPECT_EQ(q.size(), 5u);
    EXPECT_EQ(q.x, p.x);
    EXPECT_EQ(q.v, p.v);
    EXPECT_EQ(q.C, p.C);
    EXPECT_EQ(q.F, p.F);
    EXPECT_EQ(q.be, p.be);
    EXPECT_EQ(q.stress, p.stress);
    EXPECT_EQ(q.mass, p.mass);
    EXPECT_EQ(q.volume, p.volume);
    EXPECT_EQ(q.volume0, p.volume0);
    EXPECT_EQ(q.plasticStrain, p.plasticStrain);
    EXPECT_EQ(q.id, p.id);
    EXPECT_EQ(q.material, p.material);
    EXPECT_EQ(q.scalar(r), p.scalar(r));
    EXPECT_EQ(q.tensor(e), p.tensor(e));
    EXPECT_EQ(q.flag(f), p.flag(f));
    for (const auto& L : q.L)
        EXPECT_EQ(L, Mat<dim>::Zero()); // recomputed by the step, not restarted
    // Every field the table marks as restart state comes back bit for bit, whatever is added to
    // the table later.
    int restarted = 0;
    Particles<dim>::visitTable(
        [&](const FieldInfo& info, const auto& read, const auto& written) {
            if (!info.restart) return;
            ++restarted;
            EXPECT_TRUE(read == written) << info.name;
        },
        [](const char*, auto) {}, q, p);
    EXPECT_EQ(restarted, 15); // 12 built-in fields and the 3 declared above
}

TEST(ParticleIOTest, RoundTrip2D) {
    roundTrip<2>();
}
TEST(ParticleIOTest, RoundTrip3D) {
    roundTrip<3>();
}

TEST(ParticleIOTest, MissingDeclaredStateIsAnInputErrorNamingIt) {
    Particles<2> p = sample<2>(3);
    const io::PointCloud cloud = io::toPointCloud(p);
    Particles<2> q;
    q.addTensor({"elasticStress"});
    try {
        io::fromPointCloud(cloud, q, "1/particles.vtu");
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("elasticStress"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("1/particles.vtu"), std::string::npos) << e.what();
    }
}

TEST(ParticleIOTest, WrongComponentsAreAnInputError) {
    Particles<2> p = sample<2>(2);
    io::PointCloud cloud = io::toPointCloud(p);
    for (auto& a : cloud.arrays)
        if (a.name == "velocity") a.components = 1, a.f64.resize(2);
    Particles<2> q;
    EXPECT_THROW(io::fromPointCloud(cloud, q, "x.vtu"), InputError);
}

} // namespace
