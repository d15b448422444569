// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Types.hpp"
#include "particles/Region.hpp"

#include <cstdint>
#include <functional>
#include <vector>

namespace mpm {

/// Regular seeding: every grid cell overlapping region.bounds() is split into n^dim sub-cells
/// (n = perDirection) and a point is placed at each sub-cell centre,
///     x = gridOrigin + (cell + (k + 0.5) / n) h,   k in {0..n-1}^dim,
/// keeping those with region.contains(x). Each point stands for a volume (h / n)^dim.
/// Order: cells lexicographically (x fastest), and within a cell the sub-cells likewise.
/// cellSize <= 0 or perDirection < 1 is std::invalid_argument.
template <int dim>
std::vector<Vec<dim>> seedRegular(const Region<dim>& region, const Vec<dim>& gridOrigin,
                                  double cellSize, int perDirection);

/// Poisson-disk seeding (Bridson 2007) restricted to `region`: no two points closer than
/// r = minDistance, and (up to the k = 30 attempts per active point) no room for another.
///
/// Background grid of cell size r / sqrt(dim) over region.bounds() (at most one point per cell);
/// candidates are uniform in the annulus r <= |x - p| <= 2r around a random active point p.
/// Growth starts from the centre of the bounds if inside the region; then, and whenever the
/// active list empties, uniform samples in the bounds are tried as new seeds (disconnected or
/// concave parts), until 1000 consecutive samples fail. Deterministic for a given `seed`
/// (std::mt19937_64 with a portable mapping to [0, 1)). Output sorted by background-grid cell,
/// lexicographically with x fastest. minDistance <= 0 is std::invalid_argument.
template <int dim>
std::vector<Vec<dim>> seedPoissonDisk(const Region<dim>& region, double minDistance,
                                      std::uint64_t seed);

/// Minimum distance for seedPoissonDisk giving about `particlesPerCell` points per grid cell of
/// size h: r = f h / ppc^(1/dim), where f^dim is the measured bulk density of the sampling at
/// r = 1 (f = 0.785 in 2D, 0.833 in 3D; see Seeding.cpp). dim other than 2 or 3, h <= 0 or
/// ppc < 1 is std::invalid_argument.
double poissonDiskSpacing(double cellSize, int particlesPerCell, int dim);

/// Voronoi volumes of `points` clipped to `region` [002 §4.5: Poisson-disk points carry their
/// Voronoi volumes]: V_i = |{x ∈ region : x is nearer to x_i than to any other point, and
/// within 2 `spacing` of it, and not excluded}|, by midpoint quadrature on a lattice of about
/// `samplesPerSpacing` samples per `spacing` along each axis (the lattice divides region.bounds()
/// exactly, so a box region's volumes sum to its volume to round-off). Ties go to the lower index.
/// `spacing` is the points' typical distance (the Poisson-disk r); a sample farther than 2 spacing
/// from every point belongs to none. With 8 samples per spacing a 3D point gets ~900 samples, and
/// V_i is within ~1 % rms (a few % at the walls) of its exact Voronoi volume. Deterministic for any
/// thread count (integer sample counts). `excluded` (optional) removes space from every cell, e.g.
/// the inside of rigid bodies. spacing <= 0 or samplesPerSpacing < 1 is std::invalid_argument.
template <int dim>
std::vector<double> voronoiVolumes(const Region<dim>& region, const std::vector<Vec<dim>>& points,
                                   double spacing, int samplesPerSpacing,
                                   const std::function<bool(const Vec<dim>&)>& excluded = {});

/// Leave out the groups of fewer than `minCount` points, a group being the points connected
/// through neighbours at most `link` apart (single linkage): the specks a seeding leaves in
/// narrow pockets. The order of the kept points is unchanged; returns how many were left out.
/// link <= 0 is std::invalid_argument.
template <int dim>
std::size_t dropSmallClusters(std::vector<Vec<dim>>& points, double link, std::size_t minCount);

extern template std::vector<Vec<2>> seedRegular<2>(const Region<2>&, const Vec<2>&, double, int);
extern template std::vector<Vec<3>> seedRegular<3>(const Region<3>&, const Vec<3>&, double, int);
extern template std::vector<Vec<2>> seedPoissonDisk<2>(const Region<2>&, double, std::uint64_t);
extern template std::vector<Vec<3>> seedPoissonDisk<3>(const Region<3>&, double, std::uint64_t);
extern template std::vector<double> voronoiVolumes<2>(const Region<2>&, const std::vector<Vec<2>>&,
                                                      double, int,
                                                      const std::function<bool(const Vec<2>&)>&);
extern template std::vector<double> voronoiVolumes<3>(const Region<3>&, const std::vector<Vec<3>>&,
                                                      double, int,
                                                      const std::function<bool(const Vec<3>&)>&);
extern template std::size_t dropSmallClusters<2>(std::vector<Vec<2>>&, double, std::size_t);
extern template std::size_t dropSmallClusters<3>(std::vector<Vec<3>>&, double, std::size_t);

} // namespace mpm
