#include "core/eval/scene_evaluation.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "core/patch/patch_types.hpp"
#include "core/scene/surface_names.hpp"

namespace pl {

namespace {

// Moves the evaluator's patch onto `target` point by point; false if the structure differs (a
// different type, point count or domain cannot be followed point by point).
bool follow(PatchEvaluator& ev, const Patch& target, std::size_t& moved) {
  const Patch& current = ev.patch();
  if (current.type() != target.type() || current.size() != target.size() ||
      current.domain().key() != target.domain().key())
    return false;
  // Ribbon patches of two schemes (or twist estimates, or midpoint settings: the central point
  // is solved from the points with the fullness as a coefficient) share their type, points and
  // domain but not their basis: such a face is evaluated afresh.
  const auto* a = patch_as<RibbonPatch>(current);
  const auto* b = patch_as<RibbonPatch>(target);
  if (a && b &&
      (a->scheme() != b->scheme() || a->options().twists != b->options().twists ||
       a->options().fullness != b->options().fullness ||
       a->options().midpoint.has_value() != b->options().midpoint.has_value()))
    return false;
  std::vector<PatchEvaluator::PointMove> moves;
  for (std::size_t k = 0; k < target.size(); ++k)
    if (current.control_point(k) != target.control_point(k))
      moves.push_back({k, target.control_point(k)});
  ev.move_control_points(moves);
  moved += moves.size();
  return true;
}

// Moves a face's interior patch onto the offsets of `face` (an interior edit): one axpy per
// moved free point. False if the evaluator does not hold an interior patch.
bool follow_interior(PatchEvaluator& ev, const NetworkFace& face, std::size_t& moved) {
  const auto* patch = patch_as<GBInteriorPatch>(ev.patch());
  if (!patch) return false;
  std::vector<PatchEvaluator::PointMove> moves;
  for (const InteriorPointMove& m : interior_point_moves(*patch, face))
    moves.push_back({m.index, m.position});
  ev.move_control_points(moves);
  moved += moves.size();
  return true;
}

}  // namespace

SceneEvaluation::SceneEvaluation(const Scene& scene, int density, std::optional<FaceScheme> scheme,
                                 std::string source, SampleStorage storage)
    : density_(density),
      scheme_(scheme),
      source_(std::move(source)),
      storage_(storage),
      filling_(scheme, source_) {
  if (density < 1) throw std::invalid_argument("SceneEvaluation: density must be at least 1");
  sync(scene);
}

std::unique_ptr<PatchEvaluator> SceneEvaluation::make_evaluator(std::shared_ptr<Patch> patch,
                                                                int density) {
  auto tess = cache_.get(patch->domain(), density);
  return std::make_unique<PatchEvaluator>(std::move(patch), std::move(tess), storage_);
}

SyncStats SceneEvaluation::sync(const Scene& scene, const InteriorEdit* known) {
  static const Network kNoNetwork;
  if (known && scene.network && faces_in_place(known->faces))
    if (const auto up = filling_.update_interior(*scene.network, known->faces)) {
      SyncStats stats;
      sync_interior(*up, *scene.network, stats);
      return stats;
    }
  // The only step that can refuse the scene comes first: nothing has changed if it throws.
  const FillingUpdate up = filling_.update(scene.network ? *scene.network : kNoNetwork);
  SyncStats stats;
  stats.renumbered = up.renumbered;
  std::vector<SceneSurface> out;
  out.reserve(surfaces_.surfaces.size());
  sync_faces(up, out, stats);
  sync_patches(scene, out, stats);
  surfaces_.surfaces = std::move(out);
  if (up.renumbered)
    surfaces_.shared_edges = shared_edges_of(filling_.topology(), surfaces_.surfaces);
  if (up.projected_changed) surfaces_.projected_vertices = filling_.projected_vertices();
  return stats;
}

void SceneEvaluation::sync_faces(const FillingUpdate& up, std::vector<SceneSurface>& out,
                                 SyncStats& stats) {
  const Network& net = filling_.network();
  std::vector<SceneSurface>& old = surfaces_.surfaces;
  const int faces = static_cast<int>(up.previous_face.size());
  std::size_t next_refill = 0;
  for (int f = 0; f < faces; ++f) {
    const int from = up.previous_face[f];
    if (from >= 0) {  // an unchanged patch: its evaluator and samples are kept
      SceneSurface s = std::move(old.at(from));
      s.face = f;
      s.patch_side = filling_.patch_side(f);
      const std::string name = face_surface_name(net, f);
      bool changed = from != f || s.name != name;
      s.name = name;
      if (std::binary_search(up.interior_edited.begin(), up.interior_edited.end(), f))
        changed = follow_offsets(s, f, stats) || changed;
      if (changed) stats.changed_surfaces.push_back(f);
      stats.previous_surface.push_back(from);
      out.push_back(std::move(s));
      continue;
    }
    const FacePatch& fp = up.refilled.at(next_refill++);
    SceneSurface s;
    const bool same_face = !up.renumbered && f < static_cast<int>(old.size()) && old[f].face == f;
    if (same_face) s = std::move(old[f]);
    s.name = face_surface_name(net, f);
    s.face = f;
    s.patch = -1;
    s.patch_side = fp.patch_side;
    const uint64_t before = s.evaluator ? s.evaluator->revision() : 0;
    if (s.evaluator && follow(*s.evaluator, *fp.patch, stats.moved_points)) {
      if (s.evaluator->revision() != before) stats.changed_surfaces.push_back(f);
      stats.previous_surface.push_back(f);
    } else {
      const int density = s.evaluator ? s.evaluator->tessellation().density : density_;
      s.evaluator = make_evaluator(fp.patch->clone(), density);
      s.evaluator->continue_revisions_from(before);
      ++stats.rebuilt_surfaces;
      stats.changed_surfaces.push_back(f);
      stats.previous_surface.push_back(-1);
    }
    out.push_back(std::move(s));
  }
}

bool SceneEvaluation::faces_in_place(std::span<const int> faces) const {
  const std::vector<SceneSurface>& surfaces = surfaces_.surfaces;
  for (int f : faces)
    if (f < 0 || std::size_t(f) >= surfaces.size() || surfaces[std::size_t(f)].face != f)
      return false;
  return true;
}

bool SceneEvaluation::follow_offsets(SceneSurface& s, int f, SyncStats& stats) {
  const uint64_t before = s.evaluator->revision();
  if (!follow_interior(*s.evaluator, filling_.network().faces[f], stats.moved_points)) {
    const FacePatch fp = filling_.build(f);  // not expected: the patch was interior
    if (!follow(*s.evaluator, *fp.patch, stats.moved_points))
      s.evaluator = make_evaluator(fp.patch->clone(), s.evaluator->tessellation().density);
    s.evaluator->continue_revisions_from(before);
  }
  return s.evaluator->revision() != before;
}

void SceneEvaluation::sync_interior(const FillingUpdate& up, const Network& network,
                                    SyncStats& stats) {
  std::vector<SceneSurface>& surfaces = surfaces_.surfaces;
  for (int f : up.interior_edited) {
    std::vector<InteriorOffset> old = filling_.exchange_offsets(f, network.faces[f].offsets);
    try {
      if (follow_offsets(surfaces[std::size_t(f)], f, stats)) stats.changed_surfaces.push_back(f);
    } catch (...) {
      filling_.exchange_offsets(f, std::move(old));
      throw;
    }
  }
  stats.previous_surface.resize(surfaces.size());
  std::iota(stats.previous_surface.begin(), stats.previous_surface.end(), 0);
}

void SceneEvaluation::sync_patches(const Scene& scene, std::vector<SceneSurface>& out,
                                   SyncStats& stats) {
  std::vector<SceneSurface>& old = surfaces_.surfaces;
  std::size_t old_index = 0;  // first surface of patch_sources_[i] in `old`
  while (old_index < old.size() && old[old_index].patch < 0) ++old_index;
  std::vector<PatchSource> sources;
  for (std::size_t i = 0; i < scene.patches.size(); ++i) {
    const ScenePatch& sp = scene.patches[i];
    const std::string name = patch_surface_name(scene, i);
    const bool had = i < patch_sources_.size();
    const std::size_t old_first = old_index, old_count = had ? patch_sources_[i].surfaces : 0;
    old_index += old_count;
    PatchSource src{sp.patch, name, 0};
    if (had && patch_sources_[i].patch == sp.patch) {  // the same patch object: unchanged
      for (std::size_t k = 0; k < old_count; ++k) {
        SceneSurface s = std::move(old[old_first + k]);
        s.patch = static_cast<int>(i);
        const std::string n = piece_name(name, old_count, k);
        if (old_first + k != out.size() || s.name != n)
          stats.changed_surfaces.push_back(static_cast<int>(out.size()));
        stats.previous_surface.push_back(static_cast<int>(old_first + k));
        s.name = n;
        out.push_back(std::move(s));
      }
      src.surfaces = old_count;
      sources.push_back(std::move(src));
      continue;
    }
    const auto pieces = surface_pieces_of(*sp.patch);
    const bool same_count = had && pieces.size() == old_count;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      SceneSurface s;
      if (same_count) s = std::move(old[old_first + k]);
      s.name = piece_name(name, pieces.size(), k);
      s.face = -1;
      s.patch = static_cast<int>(i);
      s.patch_side.clear();
      const uint64_t before = s.evaluator ? s.evaluator->revision() : 0;
      const std::size_t index = out.size();
      if (s.evaluator && follow(*s.evaluator, *pieces[k], stats.moved_points)) {
        if (s.evaluator->revision() != before || old_first + k != index)
          stats.changed_surfaces.push_back(static_cast<int>(index));
        stats.previous_surface.push_back(static_cast<int>(old_first + k));
      } else {
        const int density = s.evaluator ? s.evaluator->tessellation().density : density_;
        s.evaluator = make_evaluator(pieces[k], density);
        s.evaluator->continue_revisions_from(before);
        ++stats.rebuilt_surfaces;
        stats.changed_surfaces.push_back(static_cast<int>(index));
        stats.previous_surface.push_back(-1);
      }
      out.push_back(std::move(s));
    }
    src.surfaces = pieces.size();
    sources.push_back(std::move(src));
  }
  if (sources.size() != patch_sources_.size() || out.size() != old.size()) stats.renumbered = true;
  patch_sources_ = std::move(sources);
}

SyncStats SceneEvaluation::set_densities(std::span<const int> densities) {
  if (densities.size() != surfaces_.surfaces.size())
    throw std::invalid_argument("set_densities needs one density per surface");
  for (int d : densities)
    if (d < 1) throw std::invalid_argument("a density must be at least 1");
  SyncStats stats;
  for (std::size_t i = 0; i < densities.size(); ++i) {
    stats.previous_surface.push_back(static_cast<int>(i));
    SceneSurface& s = surfaces_.surfaces[i];
    if (s.evaluator->tessellation().density == densities[i]) continue;
    const uint64_t before = s.evaluator->revision();
    s.evaluator = make_evaluator(s.evaluator->patch().clone(), densities[i]);
    s.evaluator->continue_revisions_from(before);
    ++stats.rebuilt_surfaces;
    stats.changed_surfaces.push_back(static_cast<int>(i));
  }
  return stats;
}

}  // namespace pl
