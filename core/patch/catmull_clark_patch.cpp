#include "core/patch/catmull_clark_patch.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "core/curve/interpolating_curve.hpp"

namespace pl {

namespace {
SurfaceJet combine_sparse(const std::vector<std::pair<int, Jet>>& w, const std::vector<Vec3>& pts) {
  // Relative to the heaviest vertex (partition of unity), as for B-splines: exact zeros where
  // only coinciding points carry weight.
  std::size_t best = 0;
  for (std::size_t i = 1; i < w.size(); ++i)
    if (w[i].second.f > w[best].second.f) best = i;
  const Vec3 ref = pts[w[best].first];
  SurfaceJet s;
  s.p = ref;
  for (const auto& [k, j] : w) {
    const Vec3 c = pts[k] - ref;
    s.p += j.f * c, s.su += j.fu * c, s.sv += j.fv * c;
    s.suu += j.fuu * c, s.suv += j.fuv * c, s.svv += j.fvv * c;
  }
  return s;
}
}  // namespace

CatmullClarkFacePatch::CatmullClarkFacePatch(std::shared_ptr<const CatmullClarkLimit> limit,
                                             int face, std::vector<Vec3> vertices)
    : Patch(std::move(vertices)),
      limit_(std::move(limit)),
      face_(face),
      support_(points_.size(), 0) {
  // The limit over a (ptex) face depends on the vertices of its patch points' stencils.
  for (const int q : limit_->face_points(face_)) {
    for (const int v : limit_->stencil_vertices(q)) support_[v] = 1;
    local_.push_back(limit_->patch_point(q, points_));
  }
}

void CatmullClarkFacePatch::set_control_point(std::size_t k, const Vec3& p) {
  Patch::set_control_point(k, p);
  if (!support_.at(k)) return;
  const auto& fp = limit_->face_points(face_);
  for (std::size_t i = 0; i < fp.size(); ++i) {
    const auto v = limit_->stencil_vertices(fp[i]);
    if (std::binary_search(v.begin(), v.end(), static_cast<int>(k)))
      local_[i] = limit_->patch_point(fp[i], points_);
  }
}

ControlPointKind CatmullClarkFacePatch::kind(std::size_t k) const {
  return limit_->boundary_vertex(static_cast<int>(k)) ? ControlPointKind::Boundary
                                                      : ControlPointKind::Inner;
}

void CatmullClarkFacePatch::basis(Vec2 x, std::span<Jet> out) const {
  assert(out.size() == size());
  std::fill(out.begin(), out.end(), Jet(0.0));
  for (const auto& [k, j] : limit_->basis(face_, x)) out[k] = j;
}

SurfaceJet CatmullClarkFacePatch::evaluate(Vec2 x) const {
  // Relative to the heaviest patch point (partition of unity), as for B-splines: exact zeros
  // where only coinciding points carry weight.
  const CatmullClarkLimit::LocalBasis b = limit_->local_basis(face_, x);
  int best = 0;
  for (int i = 1; i < b.count; ++i)
    if (b.weight[i].f > b.weight[best].f) best = i;
  const Vec3 ref = local_[b.point[best]];
  SurfaceJet s;
  s.p = ref;
  for (int i = 0; i < b.count; ++i) {
    const Jet& j = b.weight[i];
    const Vec3 c = local_[b.point[i]] - ref;
    s.p += j.f * c, s.su += j.fu * c, s.sv += j.fv * c;
    s.suu += j.fuu * c, s.suv += j.fuv * c, s.svv += j.fvv * c;
  }
  return s;
}

void CatmullClarkFacePatch::influence(std::size_t k, std::span<const Vec2> xs,
                                      std::span<Jet> out) const {
  std::fill(out.begin(), out.end(), Jet(0.0));
  if (!support_.at(k)) return;
  // Vertex k's weight in each patch point of the face, then per sample its patch's sum.
  const auto& fp = limit_->face_points(face_);
  std::vector<double> column(fp.size(), 0.0);
  for (std::size_t i = 0; i < fp.size(); ++i) {
    const auto v = limit_->stencil_vertices(fp[i]);
    const auto it = std::lower_bound(v.begin(), v.end(), static_cast<int>(k));
    if (it != v.end() && *it == static_cast<int>(k))
      column[i] = limit_->stencil_weights(fp[i])[it - v.begin()];
  }
  for (std::size_t s = 0; s < xs.size(); ++s) {
    const CatmullClarkLimit::LocalBasis b = limit_->local_basis(face_, xs[s]);
    Jet sum(0.0);
    for (int i = 0; i < b.count; ++i)
      if (column[b.point[i]] != 0) sum += b.weight[i] * column[b.point[i]];
    out[s] = sum;
  }
}

std::vector<BezierCurve> CatmullClarkFacePatch::boundary_curves() const {
  // The cubic through the side's limit points at t = 0, 1/3, 2/3, 1: exact where the side is a
  // cubic (regular faces), an interpolant elsewhere.
  std::vector<BezierCurve> sides;
  for (int s = 0; s < 4; ++s) {
    std::array<Vec3, 4> p;
    for (int k = 0; k < 4; ++k) p[k] = evaluate(domain_.side_point(s, k / 3.0)).p;
    sides.push_back(InterpolatingCurve(p).to_bezier());
  }
  return sides;
}

Vec3 CatmullClarkFacePatch::boundary_point(int side, double t) const {
  return limit_->stencil_point(face_, domain_.side_point(side, t), points_);
}

CatmullClarkPatch::CatmullClarkPatch(std::vector<Vec3> vertices,
                                     std::vector<std::vector<int>> faces)
    : Patch(std::move(vertices)),
      limit_(std::make_shared<CatmullClarkLimit>(points_.size(), faces)) {}

ControlPointKind CatmullClarkPatch::kind(std::size_t k) const {
  return limit_->boundary_vertex(static_cast<int>(k)) ? ControlPointKind::Boundary
                                                      : ControlPointKind::Inner;
}

namespace {
struct Strip {
  int face;
  Vec2 uv;
};
Strip strip_of(Vec2 x, std::size_t faces) {
  const double F = double(faces);
  const int f = std::clamp(static_cast<int>(std::floor(x.x * F)), 0, static_cast<int>(faces) - 1);
  return {f, {x.x * F - f, x.y}};
}
}  // namespace

void CatmullClarkPatch::basis(Vec2 x, std::span<Jet> out) const {
  assert(out.size() == size());
  std::fill(out.begin(), out.end(), Jet(0.0));
  const Strip s = strip_of(x, limit_->ptex_count());
  const double F = double(limit_->ptex_count());
  for (auto [k, j] : limit_->basis(s.face, s.uv)) {
    j.fu *= F, j.fuu *= F * F, j.fuv *= F;
    out[k] = j;
  }
}

SurfaceJet CatmullClarkPatch::evaluate(Vec2 x) const {
  const Strip s = strip_of(x, limit_->ptex_count());
  const double F = double(limit_->ptex_count());
  SurfaceJet j = combine_sparse(limit_->basis(s.face, s.uv), points_);
  j.su *= F, j.suu *= F * F, j.suv *= F;
  return j;
}

std::vector<BezierCurve> CatmullClarkPatch::boundary_curves() const {
  std::vector<BezierCurve> sides;
  const std::size_t F = limit_->ptex_count();
  for (int s = 0; s < 4; ++s) {
    std::vector<Vec3> p;
    const std::size_t n = (s % 2 == 0) ? F : 1;
    for (std::size_t k = 0; k <= n; ++k)
      p.push_back(evaluate(domain_.side_point(s, double(k) / n)).p);
    sides.emplace_back(std::move(p));
  }
  return sides;
}

Vec3 CatmullClarkPatch::boundary_point(int side, double t) const {
  const Strip s = strip_of(domain_.side_point(side, t), limit_->ptex_count());
  return limit_->stencil_point(s.face, s.uv, points_);
}

std::vector<std::shared_ptr<Patch>> CatmullClarkPatch::surface_pieces() const {
  // The pieces share the limit (topology, patch table, stencils); each holds its own copy of
  // the points, as every Patch does, so a drag moves index k in each of them.
  std::vector<std::shared_ptr<Patch>> r;
  for (std::size_t f = 0; f < limit_->ptex_count(); ++f)
    r.push_back(std::make_shared<CatmullClarkFacePatch>(limit_, static_cast<int>(f), points_));
  return r;
}

std::vector<std::unique_ptr<CatmullClarkFacePatch>> CatmullClarkPatch::face_patches() const {
  std::vector<std::unique_ptr<CatmullClarkFacePatch>> r;
  for (std::size_t f = 0; f < limit_->ptex_count(); ++f)
    r.push_back(std::make_unique<CatmullClarkFacePatch>(limit_, static_cast<int>(f), points_));
  return r;
}

}  // namespace pl
