#include "core/patch/exact_boundary.hpp"

#include "core/patch/patch_types.hpp"

namespace pl {

bool boundary_curves_are_exact(const Patch& patch) {
  return visit_patch_type(
      patch,
      Overloaded{
          // Every side is one polynomial curve: the boundary rows of a Bézier net, the cubic
          // sides of the bicubic classic patches, the boundary rows of the Gregory and GB
          // ribbons (a network face with interior control keeps its default filling's).
          []<OneOf<BezierPatch, InterpolatingPatch, HermitePatch, GregoryQuadPatch, GregoryTriPatch,
                   GBPatch, GBRibbonPatch, GBInteriorPatch>
                 T>(const T&) { return true; },
          // Sides of several spans or cells, or a subdivision limit: boundary_curves() is only
          // a curve on the side's control polygon (boundary_point() gives the side itself).
          []<OneOf<BSplinePatch, NurbsPatch, CoonsNetworkPatch, CatmullClarkPatch, PairJoinPatch,
                   GapFillPatch>
                 T>(const T&) { return false; },
          // Bézier sides or not, by the curves the patch was given.
          [](const RibbonPatch& p) { return p.bezier_sides(); }});
}

}  // namespace pl
