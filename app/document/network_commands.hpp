// The authoring commands of a curve network, each one undo step on the document. The geometry
// is core's (core/scene/network_edit.hpp, core/network/handle_planes.hpp); a command adds what
// the designer needs: a network where there was none, new edges where a face needs them, and a
// refusal (EditRefused, with a message; the document is unchanged) of anything that would leave
// a network the reader rejects or the filling cannot fill near the edit.
//
// Indices of new elements are known before the command runs: a new vertex, edge or face is
// appended (index = the old count), so the caller can select it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/document/command.hpp"

namespace pl {

// An empty scene: no network, no patches (File > New inside one document; undoable).
class NewSceneCommand final : public Command {
 public:
  void apply(Scene& scene) override { scene = Scene{}; }
  std::string label() const override { return "new scene"; }
};

// Appends a vertex (the scene gets a network if it had none).
class AddVertexCommand final : public Command {
 public:
  explicit AddVertexCommand(Vec3 position) : position_(position) {}
  void apply(Scene& scene) override;
  std::string label() const override { return "add vertex " + std::to_string(vertex_); }
  int vertex() const { return vertex_; }  // after apply

 private:
  Vec3 position_;
  int vertex_ = -1;
};

// Appends the edge a -> b with handles at 1/3 and 2/3 of the chord, turned into the vertices'
// tangent planes where those are defined (new_edge_handles).
class AddEdgeCommand final : public Command {
 public:
  AddEdgeCommand(int a, int b) : a_(a), b_(b) {}
  void apply(Scene& scene) override;
  std::string label() const override;

 private:
  int a_, b_, edge_ = -1;
};

// Appends a face on a closed chain given by its vertices in order, or by its edges (any order).
// Missing edges between consecutive vertices are added first (as AddEdgeCommand). The face runs
// opposite to its neighbours on shared edges; without neighbours, its normal points along
// `towards` when given (the editor passes the direction to the viewer), else the loop keeps the
// order given.
class MakeFaceCommand final : public Command {
 public:
  explicit MakeFaceCommand(std::vector<int> loop, std::optional<Vec3> towards = std::nullopt)
      : loop_(std::move(loop)), towards_(towards) {}
  static std::unique_ptr<MakeFaceCommand> from_edges(std::vector<int> edges,
                                                     std::optional<Vec3> towards = std::nullopt);
  void apply(Scene& scene) override;
  std::string label() const override;
  int face() const { return face_; }  // after apply

 private:
  std::vector<int> loop_, edges_;
  std::optional<Vec3> towards_;
  int face_ = -1, new_edges_ = 0;
};

// A face for every closed loop of boundary edges with 3 to max_sides sides.
class FillHolesCommand final : public Command {
 public:
  explicit FillHolesCommand(int max_sides = 12) : max_sides_(max_sides) {}
  void apply(Scene& scene) override;
  std::string label() const override;

 private:
  int max_sides_;
  std::vector<int> faces_;
};

// Deletes vertices (with their edges and faces), edges (with their faces) and faces; what is
// left is renumbered in order.
class DeleteCommand final : public Command {
 public:
  DeleteCommand(std::vector<int> vertices, std::vector<int> edges, std::vector<int> faces)
      : vertices_(std::move(vertices)), edges_(std::move(edges)), faces_(std::move(faces)) {}
  void apply(Scene& scene) override;
  std::string label() const override;
  const Removed& removed() const { return removed_; }  // after apply, in indices before it

 private:
  std::vector<int> vertices_, edges_, faces_;
  Removed removed_;
};
std::unique_ptr<DeleteCommand> delete_vertex_command(int v);
std::unique_ptr<DeleteCommand> delete_edge_command(int e);
std::unique_ptr<DeleteCommand> delete_face_command(int f);

// Splits edge e at parameter t (0 < t < 1) by de Casteljau: the curve is unchanged. The new
// vertex (index: the old vertex count) joins the faces that used the edge, which gain a side,
// and gets the fixed normal of the tangent plane those faces share there (edge_plane_normal).
// The label says which faces gained a side and what they are filled with now.
class SplitEdgeCommand final : public Command {
 public:
  SplitEdgeCommand(int edge, double t) : edge_(edge), t_(t) {}
  void apply(Scene& scene) override;
  std::string label() const override { return label_; }
  const Split& split() const { return split_; }  // after apply

 private:
  int edge_;
  double t_;
  Split split_;
  std::string label_;
};

// Sets a face's filling scheme; Gregory is refused on faces of other than 3 or 4 sides. A face
// that becomes Gregory loses its interior edits (degree and offsets: a Gregory face has no free
// interior), and the label says so.
class SetFaceSchemeCommand final : public Command {
 public:
  SetFaceSchemeCommand(int face, FaceScheme scheme) : face_(face), scheme_(scheme) {}
  void apply(Scene& scene) override;
  std::string label() const override {
    return "face " + std::to_string(face_) + " scheme " + scheme_keyword(scheme_) +
           (interior_dropped_ ? " (its interior edits dropped)" : "");
  }

 private:
  int face_;
  FaceScheme scheme_;
  bool interior_dropped_ = false;
};

// Names a face or an edge ("" clears the name). Callers make a SetFaceNameCommand or a
// SetEdgeNameCommand, which only say which element.
class RenameCommand : public Command {
 public:
  enum class Element { Face, Edge };
  void apply(Scene& scene) override;
  std::string label() const override;

 protected:
  RenameCommand(Element element, int index, std::string name)
      : element_(element), index_(index), name_(std::move(name)) {}

 private:
  Element element_;
  int index_;
  std::string name_;
};

class SetFaceNameCommand final : public RenameCommand {
 public:
  SetFaceNameCommand(int face, std::string name)
      : RenameCommand(Element::Face, face, std::move(name)) {}
};

class SetEdgeNameCommand final : public RenameCommand {
 public:
  SetEdgeNameCommand(int edge, std::string name)
      : RenameCommand(Element::Edge, edge, std::move(name)) {}
};

// The tangent plane of vertex v: a fixed normal (stored; the vertex's handles turn with the
// plane, so its end tangents stay in it), or none (the plane is fitted again; handles stay).
// `continuing`: part of a drag of the normal, merged with the previous such command on v.
class SetVertexNormalCommand final : public Command {
 public:
  SetVertexNormalCommand(int vertex, std::optional<Vec3> normal, bool continuing = false)
      : vertex_(vertex), normal_(normal), continuing_(continuing) {}
  void apply(Scene& scene) override;
  std::string label() const override;
  std::string merge_key() const override;

 private:
  int vertex_;
  std::optional<Vec3> normal_;
  bool continuing_;
};

}  // namespace pl
