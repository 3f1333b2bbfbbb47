// Figures of the incremental engine, each compared within this run:
//   drag_sync_ms_24_faces, drag_sync_ms_1536_faces: SceneEvaluation::sync per frame of a vertex
//     drag on the closed cube-sphere networks (GB faces, density 16, the editor's drag density):
//     a drag frame must not cost more on a big network;
//   drag_sync_ms_free_point_24_faces, _1536_faces and their ratio: the same for the centre free
//     point of a GB face (its interior control);
//   topology_sync_ms_1536_faces: the sync after deleting one face and after making it again;
//   drag_frame_ms, typed_edit_ms: the same vertex of the 1,536-face network moved by a drag
//     frame (Document::drag_to + sync) and by a typed coordinate (Document::execute + sync).
#include <cmath>

#include "app/document/document.hpp"
#include "app/document/network_commands.hpp"
#include "bench_common.hpp"
#include "core/eval/scene_evaluation.hpp"
#include "core/network/sample_networks.hpp"

namespace pl::bench {

namespace {

constexpr int kDensity = 16;

Scene cube_sphere_scene(int k) {
  Scene s;
  s.network = cube_sphere_network(k, FaceScheme::GB);
  return s;
}

// The first vertex of the largest valence: the same kind of vertex (4 edges, 4 faces) at any k.
int busiest_vertex(const Network& n) {
  std::vector<int> valence(n.vertices.size(), 0);
  for (const NetworkEdge& e : n.edges) ++valence[e.v[0]], ++valence[e.v[1]];
  return int(std::max_element(valence.begin(), valence.end()) - valence.begin());
}

// Where the drag is at frame i: a small loop around the start, in the vertex's tangent plane and
// off it.
Vec3 drag_position(const Vec3& start, int i, double size) {
  const double a = 2 * M_PI * i / 60.0;
  return start + size * Vec3(std::sin(a), 0.5 * std::sin(2 * a), 0.3 * (std::cos(a) - 1));
}

// Median sync time per frame of a vertex drag (after a warm-up that builds the columns).
double drag_sync_ms(int k, int frames) {
  Document doc(cube_sphere_scene(k));
  SceneEvaluation live(doc.scene(), kDensity, std::nullopt);
  const int v = busiest_vertex(*doc.scene().network);
  const Vec3 start = doc.scene().network->vertices[v];
  const double size = 0.2 / k;  // a fifth of a cell
  doc.begin_drag({PointRef::vertex(v)});
  for (int i = 0; i < 3; ++i) {
    doc.drag_to({drag_position(start, i, size)});
    live.sync(doc.scene());
  }
  int i = 3;
  return median_ms(frames, [&] {
    doc.drag_to({drag_position(start, i++, size)});  // outside the timed sync would be fairer,
    live.sync(doc.scene());                          // but drag_to is O(E) too: keep it honest
  });
}

// The same for the centre free point of face 0 (a GB face: its interior control), dragged off
// its default position: only that face changes, whatever the size of the network. The sync is
// told what changed by the document's record of its revisions, as the editor's is.
double free_point_drag_sync_ms(int k, int frames) {
  Document doc(cube_sphere_scene(k));
  SceneEvaluation live(doc.scene(), kDensity, std::nullopt);
  const PointRef centre = PointRef::free_point(0, InteriorOffset{.centre = true});
  const Vec3 start = point_position(doc.scene(), centre);
  const double size = 0.2 / k;
  doc.begin_drag({centre});
  uint64_t synced = doc.revision();
  const auto step = [&](int i) {
    doc.drag_to({drag_position(start, i, size)});
    const auto faces = doc.interior_faces_since(synced);
    const InteriorEdit known{faces ? *faces : std::vector<int>{}};
    live.sync(doc.scene(), faces ? &known : nullptr);
    synced = doc.revision();
  };
  int i = 0;
  for (; i < 3; ++i) step(i);
  return median_ms(frames, [&] { step(i++); });
}

}  // namespace

void bench_engine(const Options& o) {
  const int frames = o.quick ? 5 : 61;
  const int small = 2, large = o.quick ? 4 : 16;  // 24 and 1,536 faces
  figure("drag_sync_ms_24_faces", drag_sync_ms(small, frames), "ms");
  figure(o.quick ? "drag_sync_ms_96_faces" : "drag_sync_ms_1536_faces", drag_sync_ms(large, frames),
         "ms");
  const double free_small = free_point_drag_sync_ms(small, frames),
               free_large = free_point_drag_sync_ms(large, frames);
  figure("drag_sync_ms_free_point_24_faces", free_small, "ms");
  figure(o.quick ? "drag_sync_ms_free_point_96_faces" : "drag_sync_ms_free_point_1536_faces",
         free_large, "ms");
  figure("drag_sync_free_point_ratio_large_over_small", free_large / free_small, "x");

  // A topology edit: delete a face, make it again; every other face keeps its evaluator.
  {
    Document doc(cube_sphere_scene(large));
    SceneEvaluation live(doc.scene(), kDensity, std::nullopt);
    const std::vector<int> loop = doc.scene().network->faces[7].loop;
    std::vector<double> ms;
    int face = 7;
    for (int r = 0; r < (o.quick ? 2 : 7); ++r) {
      doc.execute(delete_face_command(face));
      face = int(doc.scene().network->faces.size());  // where the face is made again
      ms.push_back(median_ms(1, [&] { live.sync(doc.scene()); }));
      doc.execute(std::make_unique<MakeFaceCommand>(loop));
      ms.push_back(median_ms(1, [&] { live.sync(doc.scene()); }));
    }
    std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
    figure(o.quick ? "topology_sync_ms_96_faces" : "topology_sync_ms_1536_faces", ms[ms.size() / 2],
           "ms");
  }

  // The same vertex dragged, then typed: both at the drag density, so the figures compare the
  // document and engine paths, not two densities.
  {
    Document doc(cube_sphere_scene(large));
    SceneEvaluation live(doc.scene(), kDensity, std::nullopt);
    const int v = busiest_vertex(*doc.scene().network);
    const Vec3 start = doc.scene().network->vertices[v];
    const double size = 0.2 / large;
    doc.begin_drag({PointRef::vertex(v)});
    int i = 0;
    for (; i < 3; ++i) {
      doc.drag_to({drag_position(start, i, size)});
      live.sync(doc.scene());
    }
    const double drag = median_ms(frames, [&] {
      doc.drag_to({drag_position(start, i++, size)});
      live.sync(doc.scene());
    });
    doc.end_drag();
    live.sync(doc.scene());
    // Typed coordinates: x, then y, then z of the same vertex, each one undo step.
    const double typed = median_ms(frames, [&] {
      Vec3 p = doc.scene().network->vertices[v];
      p[i % 3] += (i % 2 ? 1 : -1) * 0.01 / large;
      ++i;
      doc.execute(
          std::make_unique<MovePointsCommand>(std::vector{PointRef::vertex(v)}, std::vector{p}));
      live.sync(doc.scene());
    });
    figure("drag_frame_ms", drag, "ms");
    figure("typed_edit_ms", typed, "ms");
  }
}

}  // namespace pl::bench
