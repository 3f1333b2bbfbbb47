// The basis functions of the GB patches at a domain vertex, where the corner weights are 0/0:
// their exact limits from inside the domain.
#pragma once

#include <span>

#include "core/math/jet.hpp"
#include "core/math/vec.hpp"

namespace pl {

class GBPatch;
class GBRibbonPatch;

// Points of a central-point GB patch closer than this to a domain vertex (domain size ~2) are
// evaluated through the vertex limit plus a first-order Taylor step: the corner weights are
// 0/0 at the vertex itself and lose their digits next to it.
inline constexpr double kGBVertexRadius = 1e-10;

// Central-point GB at vertex v, approached along the ray to the domain centre: the value is the
// corner point alone; first derivatives do not depend on the direction, second derivatives in
// general do (those of the corner weights grow like 1 / distance^2 towards the vertex).
void gb_vertex_basis(const GBPatch& patch, int v, std::span<Jet> out);

// Independent-ribbon GB at vertex v (the end of side v, the start of side v+1): the corner
// point, first and second derivatives along both sides from the two boundary curves, and the
// mean of the two ribbons' twists for the mixed term (the limit depends on the direction there).
void gb_ribbon_corner_basis(const GBRibbonPatch& patch, int v, std::span<Jet> out);

// The value and gradient of j moved by a first-order Taylor step delta: the vertex limits
// applied at a point within rounding distance of the vertex.
inline void taylor_step(Jet& j, Vec2 delta) {
  j.f += j.fu * delta.x + j.fv * delta.y;
  j.fu += j.fuu * delta.x + j.fuv * delta.y;
  j.fv += j.fuv * delta.x + j.fvv * delta.y;
}

}  // namespace pl
