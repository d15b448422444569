// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "levelset/LevelSetFile.hpp"
#include "rigid/Shape.hpp"

#include <string>
#include <vector>

namespace mpm {

/// A body given by a signed-distance grid (`type: levelSet`, 3D only; in 2D the type is an
/// InputError). Key: `file`, a `.vti` written by surfaceToLevelSet (docs/levelSets.md), read
/// once. The grid is in the body frame (origin at the centroid, principal axes).
///
/// Path resolution: a relative `file` is taken from the case directory (Dictionary::getPath); a
/// file that is not found is an InputError at `file` naming the path tried.
///
/// φ and n [004 Eq. 11–13]: φ(x) = Σ_i w_i(x) φ_i and ∇φ = Σ_i ∇w_i(x) φ_i with the quadratic
/// B-spline kernel (src/kernels/Kernels.hpp) on the level-set grid, n = ∇φ/|∇φ|. Near the grid
/// boundary the stencil's missing node is a ghost extrapolated linearly from the two nodes
/// inside (φ_{-1} = 2φ_0 − φ_1), so linear fields are reproduced up to the boundary.
///
/// Outside the grid box: φ(x) = φ(p) + |x − p|, p the nearest point of the box, φ(p)
/// interpolated as above (continuous across the box faces). Since the grid pads the body, φ(p)
/// is positive and points outside the grid are never in contact. n is the gradient of that
/// expression: (x − p)/|x − p| along the axes where x is outside, ∂φ/∂x at p along the others.
///
/// Mass properties from the file: volume and unit-density principal moments. The file's
/// centroid and rotation (body frame → mesh frame) give the body's default pose (meshPose()).
///
/// Surface (for output): marching tetrahedra over the grid cells (each cube split into six
/// tetrahedra along its main diagonal, so neighbours share faces), vertices on grid edges by
/// linear interpolation of φ, triangles oriented outward (towards φ > 0), shared vertices
/// merged. Computed once, on construction.
class LevelSetShape : public Shape<3> {
public:
    explicit LevelSetShape(const Dictionary& dict);
    explicit LevelSetShape(levelset::LevelSet levelSet);

    double distance(const Vec3& x, Vec3& normal) const override;
    double volume() const override { return ls_.volume; }
    Vec3 unitInertia() const override { return ls_.principalMoments; }
    double boundingRadius() const override { return boundingRadius_; }
    void surface(std::vector<Vec3>& points, std::vector<std::vector<int>>& cells) const override;
    /// The file's centroid and rotation: x_mesh = centroid + rotation · x_body.
    bool meshPose(Vec3& centroid, Mat3& rotation) const override {
        centroid = ls_.centroid;
        rotation = ls_.rotation;
        return true;
    }

    double samplingSpacing() const override { return ls_.grid.spacing; }
    const levelset::LevelSet& levelSet() const { return ls_; }
    /// Lower and upper corners of the grid box.
    const Vec3& gridMin() const { return lo_; }
    const Vec3& gridMax() const { return hi_; }

private:
    void setup();
    /// φ and ∇φ at x inside the grid box (x is clamped to it).
    double interpolate(const Vec3& x, Vec3& gradient) const;
    void buildSurface();

    levelset::LevelSet ls_;
    Vec3 lo_ = Vec3::Zero();
    Vec3 hi_ = Vec3::Zero();
    double boundingRadius_ = 0.0;
    std::vector<Vec3> surfacePoints_;
    std::vector<std::vector<int>> surfaceCells_;
};

} // namespace mpm
