// patchlab.Document: a scene with the editor's commands (app/document), each one undo step, and
// undo/redo that restore the scene bit for bit. A refused command raises EditRefused and changes
// nothing, as in the editor.
#include <filesystem>

#include "app/cli/load_input.hpp"
#include "app/document/curve_commands.hpp"
#include "app/document/document.hpp"
#include "app/document/interior_commands.hpp"
#include "app/document/network_commands.hpp"
#include "app/python/bindings.hpp"

namespace pl::python {

namespace {

struct PyDocument {
  Document document;
};

std::string fspath(const py::handle& path) {
  return py::str(py::module_::import("os").attr("fspath")(path));
}

std::vector<Vec3> to_points(const py::sequence& points, const char* what) {
  std::vector<Vec3> out;
  for (const py::handle& p : points) out.push_back(to_point(p, what));
  return out;
}

FaceScheme face_scheme(const std::string& name) {
  if (name == "auto") return FaceScheme::Auto;
  if (name == "gregory") return FaceScheme::Gregory;
  if (name == "gb") return FaceScheme::GB;
  throw py::value_error("scheme takes \"auto\", \"gregory\" or \"gb\", got \"" + name + "\"");
}

CurveType curve_type(const std::string& name) {
  for (CurveType t : {CurveType::Bezier, CurveType::Interpolating, CurveType::Hermite,
                      CurveType::BSpline, CurveType::Nurbs})
    if (curve_type_name(t) == name) return t;
  throw py::value_error("unknown curve type \"" + name +
                        "\" (bezier, interpolating, hermite, bspline or nurbs)");
}

// The index a new vertex or face gets: the count before the command (network_commands.hpp).
// Read before running it: the document does not keep a command once it has run.
template <class T>
int count(const PyDocument& d, std::vector<T> Network::*elements) {
  const Scene& scene = d.document.scene();
  return scene.network ? static_cast<int>(((*scene.network).*elements).size()) : 0;
}

// Runs a command; returns its label. The geometry work runs without the GIL.
std::string run(PyDocument& d, std::unique_ptr<Command> command) {
  py::gil_scoped_release release;
  return d.document.execute(std::move(command));
}

// Moves one point through MovePointsCommand (what a typed coordinate does in the editor).
std::string move(PyDocument& d, PointRef ref, const py::handle& p, bool keep_plane) {
  const Vec3 to = to_point(p, "the position");
  if (!point_exists(d.document.scene(), ref))
    throw py::index_error("there is no " + describe(ref) + " in the scene");
  return run(d, std::make_unique<MovePointsCommand>(
                    std::vector<PointRef>{ref}, std::vector<Vec3>{to},
                    keep_plane ? HandleMode::KeepPlane : HandleMode::RotatePlane));
}

}  // namespace

void bind_document(py::module_& m) {
  py::class_<PyDocument>(m, "Document",
                         "A scene edited with the editor's commands: each one undo step, a "
                         "refused one raises EditRefused and changes nothing.")
      .def(py::init([](const std::optional<PyScene>& scene) {
             return PyDocument{Document(scene ? scene->scene : Scene{})};
           }),
           py::arg("scene") = py::none(), "A document of a copy of `scene` (or empty), untitled.")
      .def_static(
          "open",
          [](const py::object& path) {
            const std::string file = fspath(path);
            py::gil_scoped_release release;
            return PyDocument{Document(load_scene_file(file), file)};
          },
          py::arg("path"), "The document of a scene file (.json or .gbp).")
      .def_property_readonly(
          "scene",
          [](const PyDocument& d) {
            const std::string path = d.document.path().string();
            return PyScene{d.document.scene(), path.empty() ? "<document>" : path};
          },
          "A copy of the scene as it is now.")
      .def_property_readonly("path", [](const PyDocument& d) { return d.document.path().string(); })
      .def_property_readonly("dirty", [](const PyDocument& d) { return d.document.dirty(); })
      .def_property_readonly("can_undo", [](const PyDocument& d) { return d.document.can_undo(); })
      .def_property_readonly("can_redo", [](const PyDocument& d) { return d.document.can_redo(); })
      .def_property_readonly("undo_label",
                             [](const PyDocument& d) { return d.document.undo_label(); })
      .def_property_readonly("redo_label",
                             [](const PyDocument& d) { return d.document.redo_label(); })
      .def(
          "undo", [](PyDocument& d) { return d.document.undo(); },
          "Undoes one step; False if none.")
      .def(
          "redo", [](PyDocument& d) { return d.document.redo(); },
          "Redoes one step; False if none.")
      .def(
          "save", [](PyDocument& d) { d.document.save(); },
          "Saves to the document's file (atomic; DataError keeps the previous file).")
      .def(
          "save_as",
          [](PyDocument& d, const py::object& path) { d.document.save_as(fspath(path)); },
          py::arg("path"), "Saves to `path` (.json or .gbp) and makes it the document's file.")
      .def(
          "add_vertex",
          [](PyDocument& d, const py::handle& p) {
            const int vertex = count(d, &Network::vertices);  // appended: the old count
            run(d, std::make_unique<AddVertexCommand>(to_point(p, "add_vertex")));
            return vertex;
          },
          py::arg("position"), "Appends a network vertex; returns its index.")
      .def(
          "add_edge",
          [](PyDocument& d, int a, int b) {
            return run(d, std::make_unique<AddEdgeCommand>(a, b));
          },
          py::arg("a"), py::arg("b"),
          "Appends the edge a -> b, its handles at the chord's thirds in the vertices' planes.")
      .def(
          "make_face",
          [](PyDocument& d, std::vector<int> loop, const std::optional<py::object>& towards) {
            std::optional<Vec3> dir;
            if (towards) dir = to_point(*towards, "towards");
            const int face = count(d, &Network::faces);
            run(d, std::make_unique<MakeFaceCommand>(std::move(loop), dir));
            return face;
          },
          py::arg("loop"), py::arg("towards") = py::none(),
          "Appends a face on the closed chain of vertices `loop` (missing edges added); returns "
          "its index.")
      .def(
          "fill_holes",
          [](PyDocument& d, int max_sides) {
            return run(d, std::make_unique<FillHolesCommand>(max_sides));
          },
          py::arg("max_sides") = 12,
          "A face on every closed boundary loop of 3 to max_sides sides.")
      .def(
          "delete",
          [](PyDocument& d, std::vector<int> vertices, std::vector<int> edges,
             std::vector<int> faces) {
            return run(d, std::make_unique<DeleteCommand>(std::move(vertices), std::move(edges),
                                                          std::move(faces)));
          },
          py::arg("vertices") = std::vector<int>{}, py::arg("edges") = std::vector<int>{},
          py::arg("faces") = std::vector<int>{},
          "Deletes vertices (with their edges and faces), edges and faces; the rest is "
          "renumbered in order.")
      .def(
          "split_edge",
          [](PyDocument& d, int edge, double t) {
            return run(d, std::make_unique<SplitEdgeCommand>(edge, t));
          },
          py::arg("edge"), py::arg("t") = 0.5, "Splits an edge at t by de Casteljau.")
      .def(
          "set_face_scheme",
          [](PyDocument& d, int face, const std::string& scheme) {
            return run(d, std::make_unique<SetFaceSchemeCommand>(face, face_scheme(scheme)));
          },
          py::arg("face"), py::arg("scheme"), "\"auto\", \"gregory\" or \"gb\".")
      .def(
          "set_face_degree",
          [](PyDocument& d, int face, int degree) {
            return run(d, std::make_unique<SetFaceDegreeCommand>(face, degree));
          },
          py::arg("face"), py::arg("degree"), "The degree of a GB face's free interior.")
      .def(
          "set_face_name",
          [](PyDocument& d, int face, std::string name) {
            return run(d, std::make_unique<SetFaceNameCommand>(face, std::move(name)));
          },
          py::arg("face"), py::arg("name"))
      .def(
          "set_vertex_normal",
          [](PyDocument& d, int vertex, const std::optional<py::object>& normal) {
            std::optional<Vec3> n;
            if (normal) n = to_point(*normal, "the normal");
            return run(d, std::make_unique<SetVertexNormalCommand>(vertex, n));
          },
          py::arg("vertex"), py::arg("normal"),
          "A fixed tangent-plane normal (the handles turn with it), or None: fitted again.")
      .def(
          "move_vertex",
          [](PyDocument& d, int v, const py::handle& p) {
            return move(d, PointRef::vertex(v), p, true);
          },
          py::arg("vertex"), py::arg("position"), "Moves a vertex, carrying its handles.")
      .def(
          "move_handle",
          [](PyDocument& d, int edge, int which, const py::handle& p, bool keep_plane) {
            return move(d, PointRef::handle(edge, which), p, keep_plane);
          },
          py::arg("edge"), py::arg("which"), py::arg("position"), py::arg("keep_plane") = true,
          "Moves handle 0 or 1 of an edge, kept in its vertex's tangent plane unless "
          "keep_plane is False (then the plane turns with it).")
      .def(
          "move_patch_point",
          [](PyDocument& d, int patch, int k, const py::handle& p) {
            return move(d, PointRef::patch_point(patch, k), p, true);
          },
          py::arg("patch"), py::arg("k"), py::arg("position"),
          "Moves control point k of an explicit patch.")
      .def(
          "add_curve",
          [](PyDocument& d, const std::string& type, const py::sequence& points) {
            const int curve = static_cast<int>(d.document.scene().curves.size());
            run(d, std::make_unique<AddCurveCommand>(curve_type(type),
                                                     to_points(points, "add_curve")));
            return curve;
          },
          py::arg("type"), py::arg("points"),
          "Appends a free curve (bezier, interpolating, hermite, bspline, nurbs) as the "
          "editor's new-curve tool makes it; returns its index.")
      .def(
          "move_curve_point",
          [](PyDocument& d, int curve, int k, const py::handle& p) {
            return run(
                d, std::make_unique<MoveCurvePointCommand>(curve, k, to_point(p, "the position")));
          },
          py::arg("curve"), py::arg("k"), py::arg("position"),
          "Moves control point k of a free curve.");
}

}  // namespace pl::python
