// Each surface's density from its size on screen, within a triangle budget: what keeps drawing
// and memory bounded on big networks (1,536 faces at one density of 48 are 4.2 M samples, which
// no view needs: most faces are a few dozen pixels wide). GUI-free: the caller measures sizes on
// screen (bounding_sphere, projected by its camera).
//
// Densities are chosen from a chain of levels max, max/2, max/4, ... (down to min): neighbouring
// faces at different levels then share every sample of the coarser one's boundary, so the seams
// between them are T-junctions on the curve, not gaps between two different polylines.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "core/patch/patch.hpp"

namespace pl {

struct DensityBudget {
  int min_density = 2;
  int max_density = 48;
  double pixels_per_segment = 6;   // a boundary sample every this many pixels on screen
  std::size_t triangles = 600000;  // for all surfaces together
};

struct Sphere {
  Vec3 centre{0};
  double radius = 0;
};
// A sphere containing the patch (its control points' centroid and farthest control point; every
// patch type here lies in the convex hull of its points).
Sphere bounding_sphere(const Patch& patch);

// The levels of a budget: max_density, max/2, max/4, ... while >= min_density (rounded down).
std::vector<int> density_levels(const DensityBudget& budget);

struct SurfaceSize {
  double pixels = 0;          // the surface's diameter on screen
  std::size_t triangles = 0;  // its triangles at `density`
  int density = 1;            // (a surface's triangles grow as density^2)
  // Whether `density` was chosen from the surface's size on screen (by an earlier choice): only
  // then is one level finer than needed kept. A density set otherwise (a view's uniform start)
  // goes to what the size asks for.
  bool fitted = true;
};

// One density per surface: the level that gives a sample every pixels_per_segment pixels across
// its diameter, lowered level by level for the largest surfaces first while the total exceeds the
// budget. A surface whose fitted density is already one level finer than it needs keeps it when
// the budget allows (no re-evaluation for a small zoom).
std::vector<int> choose_densities(std::span<const SurfaceSize> sizes, const DensityBudget& budget);

// The highest level at which every surface fits the budget at one density.
int uniform_density(std::span<const SurfaceSize> sizes, const DensityBudget& budget);

}  // namespace pl
