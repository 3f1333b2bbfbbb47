// Interior control of a network GB face (the face keys "degree" and "offsets",
// docs/scene-format.md, "Interior control"). A face of degree d is
//   S_d(x) = F(x) + sum over free points p of offset_p phi^d_p(x),
// F the face's default filling (gb_face_patch of its cubic Chiyokura–Kimura ribbons: exactly the
// face without interior control) and phi^d_p the blend of free point p in the degree-d GB net
// (core/patch/gb/gb_interior_patch.hpp). So:
//  - with no offsets the face is its default filling at every degree: raising or lowering the
//    degree alone never changes the surface;
//  - the boundary curves and cross-boundary derivatives are F's whatever the offsets (every
//    phi_p vanishes with its first derivatives on the boundary): G1 with the neighbours is F's;
//  - moving a free point by delta moves the surface by delta phi_p: one influence column.
// The free points are shown where a GB net point would sit: at their defaults, the default-net
// rule (core/patch/gb/default_net.hpp) applied to the degree-d .gbp net whose rings 0 and 1 are
// the face sides' cubic ribbons elevated exactly to degree d (a corner twist, stored once in that
// net, is the mean of the two ribbons' twists), plus their offsets. The defaults are recomputed
// from the boundary whenever the network changes and the offsets are kept, so the interior
// follows the boundary.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "core/network/face_ribbons.hpp"
#include "core/network/gb_face.hpp"
#include "core/patch/gb/gb_interior_patch.hpp"
#include "core/scene/network.hpp"

namespace pl {

// The GB patch of a network face with degree d and these offsets: the default filling
// gb_face_patch(ribbons) (gb_face.hpp) itself for degree 3 without offsets, the interior form
// below otherwise (gb_face_interior_form). Throws std::invalid_argument like gb_face_patch and
// gb_interior_face_patch.
std::unique_ptr<Patch> gb_face_patch(const FaceRibbons& ribbons, int degree,
                                     std::span<const InteriorOffset> offsets,
                                     GBDomainKind* used = nullptr);
// Whether gb_face_patch gives the interior form (GBInteriorPatch) for this degree and offsets:
// every degree but 3, and degree 3 with offsets.
inline bool gb_face_interior_form(int degree, std::span<const InteriorOffset> offsets) {
  return degree != 3 || !offsets.empty();
}
// Always the interior form, at any degree (ribbons as the network gives them).
std::unique_ptr<GBInteriorPatch> gb_face_interior_patch(const FaceRibbons& ribbons, int degree,
                                                        std::span<const InteriorOffset> offsets,
                                                        GBDomainKind* used = nullptr);

// The face of degree d with these offsets over the default filling `filling`, built from
// `ribbons` as filled (reflex corners already oriented, gb_face.hpp: ribbons_as_filled). Throws
// std::invalid_argument for an offset the face cannot carry (interior_offset_problem, a moved
// central point on a face too concave for its weight) or a degree the filling's domain cannot
// carry.
std::unique_ptr<GBInteriorPatch> gb_interior_face_patch(const FaceRibbons& ribbons,
                                                        GBRibbonPatch filling, int degree,
                                                        std::span<const InteriorOffset> offsets);

// The default positions of the degree-d net of a face with these (network) ribbons, in .gbp
// order (GBPatch::point_count(n, d) points): rings 0 and 1 the elevated G1 data, the free points
// at their defaults. The same net the face's GBInteriorPatch shows before its offsets are added.
std::vector<Vec3> gb_face_default_net(const FaceRibbons& ribbons, int degree);

// The .gbp index of a free point's name (0 for the centre) and the name stored for a free net
// index (the owning ribbon's [i, j, k] in .gbp order: k <= j <= d-1-k).
std::size_t interior_point_index(int sides, int degree, const InteriorOffset& at);
InteriorOffset interior_point_name(int sides, int degree, std::size_t index);

// The offsets of the same face re-fitted for another degree (raise or lower, 3 <= d <= 15): the
// least-squares fit of the displacement field sum_p offset_p phi^old_p by the new degree's free
// blends over a dense sample of the face's domain, exact where the new degree represents it.
// No offsets give no offsets; the face's surface with zero offsets does not depend on the degree.
// Offsets whose fitted length is below 1e-14 of the largest are left out. Throws
// std::invalid_argument for a degree out of range or an offset the old degree cannot carry.
std::vector<InteriorOffset> gb_face_offsets_for_degree(const FaceRibbons& ribbons, int old_degree,
                                                       std::span<const InteriorOffset> offsets,
                                                       int new_degree);

}  // namespace pl
