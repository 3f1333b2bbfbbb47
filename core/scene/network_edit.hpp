// Authoring edits of a curve network: adding, connecting, deleting and splitting its elements.
// Every function either leaves a valid network (validate_network accepts it) with consistent
// indices, or throws EditRefused with a message for the designer and changes nothing.
// Placing handles in tangent planes is geometry of the filling (core/network/handle_planes.hpp);
// these functions take the handles and normals they need as arguments.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/patch/transfinite/ribbon_scheme.hpp"
#include "core/scene/network.hpp"

namespace pl {

// A request that would make the network invalid, or names something that does not exist.
class EditRefused : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Appends a vertex (with no fixed normal); returns its index.
int add_vertex(Network& network, const Vec3& position);

// Appends the edge a -> b with the given handles; returns its index. Refused: a missing vertex,
// a == b, a and b already joined.
int add_edge(Network& network, int a, int b, const std::array<Vec3, 2>& handles);

// The edge joining a and b (either direction), or -1.
int edge_between(const Network& network, int a, int b);

// The vertex loop of a closed chain of edges (each of their vertices on exactly two of them),
// starting at the first edge's start. Refused: fewer than three edges, a missing or repeated
// edge, a chain that is open, branches or is several loops.
std::vector<int> loop_of_edges(const Network& network, std::span<const int> edges);

// The consecutive vertex pairs of a loop that no edge joins yet.
std::vector<std::array<int, 2>> missing_loop_edges(const Network& network,
                                                   std::span<const int> loop);

// `loop` in the direction a new face must run: opposite to the faces already using its edges
// (so shared edges are traversed in opposite directions). A loop with no such neighbour keeps
// its order unless `towards` is given: then its right-hand (Newell) normal points along
// `towards` (the editor passes the direction to the viewer, so a new face faces the camera).
// Refused: fewer than 3 vertices, a missing or repeated vertex, a missing edge, an edge already
// used by two faces, neighbours that disagree on the direction, a face on the same vertices.
std::vector<int> oriented_face_loop(const Network& network, std::vector<int> loop,
                                    std::optional<Vec3> towards = std::nullopt);

// Appends a face on `loop` (checked and oriented by oriented_face_loop); returns its index.
int add_face(Network& network, std::vector<int> loop, std::optional<Vec3> towards = std::nullopt);

// The closed loops of boundary edges (edges used by exactly one face), each in the direction a
// face filling it must run. Vertices where several boundary loops touch are not crossed: a loop
// through one is left out.
std::vector<std::vector<int>> boundary_loops(const Network& network);

// Adds a face for every boundary loop with min_sides to max_sides sides; returns the new faces.
// Refused when there is none.
std::vector<int> fill_holes(Network& network, int min_sides = 3, int max_sides = 12);

// What a deletion removed, in indices before it.
struct Removed {
  std::vector<int> vertices, edges, faces;
};
// Deletes the given elements and what depends on them (a vertex's edges, an edge's faces), then
// renumbers what is left in its order. Refused: an index that does not exist.
Removed delete_elements(Network& network, std::span<const int> vertices, std::span<const int> edges,
                        std::span<const int> faces);

struct Split {
  int vertex = -1;         // the new vertex
  int edge = -1;           // the new edge: from the new vertex to the old edge's end
  std::vector<int> faces;  // the faces that gained a side
};
// Splits edge e at parameter t (0 < t < 1) with de Casteljau's construction, so the two edges
// trace the old curve: edge e keeps its start and runs to the new vertex, a new edge runs on to
// e's old end. The new vertex joins every face that used e (which gains a side; a Gregory face
// that no longer can be one becomes Auto, i.e. GB) and gets `normal` as its fixed normal (its two
// end tangents are collinear, so a face needs it; see handle_planes.hpp). Refused: t outside
// (0, 1), a missing edge, a face using e without a normal.
Split split_edge(Network& network, int e, double t, std::optional<Vec3> normal);

// Scheme and names. A Gregory scheme is refused on a face with other than 3 or 4 sides.
void set_face_scheme(Network& network, int face, FaceScheme scheme);
void set_face_name(Network& network, int face, std::string name);
void set_edge_name(Network& network, int edge, std::string name);

// The fixed normal of vertex v (normalised), or none: the plane is fitted again. Refused: a zero
// or non-finite normal.
void set_vertex_normal(Network& network, int v, std::optional<Vec3> normal);

// `normal` made unit length as the scene reader makes a file's normals: glm::normalize repeated
// until that changes it no more (or, where a few vectors normalise into each other in a cycle,
// the smallest of them). A normal stored like this survives save and open bit for bit. normal
// must be finite and non-zero.
Vec3 stored_normal(const Vec3& normal);

// The name of a scheme as the file and the interface spell it ("auto", "gregory", "gb",
// "side-based", "corner-based", "generalized-coons", "composite-ribbon", "midpoint",
// "midpoint-coons", "elastic").
std::string scheme_keyword(FaceScheme scheme);
// The scheme a keyword names (every keyword of scheme_keyword, "auto" included), or none.
std::optional<FaceScheme> parse_scheme_keyword(std::string_view keyword);
// Every scheme a face can be filled with (Auto left out), in the order of the enum: the one list
// the comparison, the CLI and the documentation go through.
std::span<const FaceScheme> all_face_schemes();
// The keywords of all_face_schemes() joined by ", " (for messages: "allowed: ...").
std::string face_scheme_keywords();
// True for the ribbon-based transfinite schemes (every scheme but Auto, Gregory and GB): they
// take any number of sides >= 3 but only convex faces (their parameterizations are defined on
// convex domains).
bool is_ribbon_scheme(FaceScheme scheme);
// The transfinite scheme a ribbon scheme evaluates (none for Auto, Gregory, GB).
std::optional<transfinite::RibbonScheme> ribbon_scheme_of(FaceScheme scheme);

}  // namespace pl
