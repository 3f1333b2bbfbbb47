// The boundary data every network face is filled from: per face side, the edge's cubic and the
// cubic "second row" carrying the Chiyokura–Kimura cross-boundary tangents. Gregory and GB
// faces are both built from it, so they meet their neighbours with the same tangent planes.
#pragma once

#include <array>
#include <vector>

#include "core/network/chiyokura_kimura.hpp"
#include "core/network/tangent_planes.hpp"
#include "core/scene/network.hpp"

namespace pl {

struct CubicRibbon {             // along face side i, in face-side direction (loop[i] -> loop[i+1])
  std::array<Vec3, 4> boundary;  // the edge's cubic Bézier control points
  std::array<Vec3, 4>
      inner;  // the cubic second row: boundary[j] + (cross-boundary tangent data)/3,
              // pointing into the face; inner[1], inner[2] are the two Chiyokura–
              // Kimura points of this side; inner[0], inner[3] the corner twists' row ends
  bool operator==(const CubicRibbon&) const = default;
};
struct FaceRibbons {
  std::vector<CubicRibbon> sides;
  bool operator==(const FaceRibbons&) const = default;
};

// One FaceRibbons per face; also fills projected vertices. Throws DataError (empty source; the
// caller names the file) for a network it cannot build tangent planes or fields for.
std::vector<FaceRibbons> build_face_ribbons(const Network&, const NetworkTopology&,
                                            std::vector<ProjectedVertex>& projected);

// The ribbons of one face from the fields of its edges (cross[e] for every edge e of the face):
// the incremental path of the editor.
FaceRibbons face_ribbons(const Network& network, const NetworkTopology& topology,
                         const std::vector<EdgeCrossTangents>& cross, int face);

}  // namespace pl
