// Reading rules of a scene that need its geometry, not just its syntax: checked after parsing and
// before any evaluation, each failure a DataError naming the file and the JSON path.
#pragma once

#include <span>
#include <string>

#include "core/scene/scene.hpp"

namespace pl {

// The control points of the network and of every patch span at least kMinSpan
// (core/io/input_limits.hpp); coordinates are bounded by the reader (JsonNode::point).
void check_spans(const Scene& scene, const std::string& source);

// Every network face's boundary, seen along the face's normal (Newell's, of the sampled
// boundary), is a simple loop: a face whose sides cross (a pentagram) has no inside to fill.
void check_face_loops(const Network& network, const NetworkTopology& topology,
                      const std::string& source);

// Both of the above.
void check_scene(const Scene& scene, const std::string& source);

// Throws DataError(source, where, ...) if points (two or more) span less than kMinSpan.
void check_span(std::span<const Vec3> points, const std::string& source, const std::string& where);

// The span of points: the length of their bounding box's diagonal (0 for fewer than two).
double span_of(std::span<const Vec3> points);

}  // namespace pl
