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
  // The limit over a (ptex) face depends on the faces around its base face's vertices.
  const auto& faces = limit_->faces();
  const auto& mine = faces[limit_->ptex_face(face_)];
  for (const auto& f : faces)
    if (std::any_of(f.begin(), f.end(),
                    [&](int v) { return std::count(mine.begin(), mine.end(), v) > 0; }))
      for (int v : f) support_[v] = 1;
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
  return combine_sparse(limit_->basis(face_, x), points_);
}

void CatmullClarkFacePatch::influence(std::size_t k, std::span<const Vec2> xs,
                                      std::span<Jet> out) const {
  for (std::size_t s = 0; s < xs.size(); ++s) {
    out[s] = Jet(0.0);
    if (!support_[k]) continue;
    for (const auto& [v, j] : limit_->basis(face_, xs[s]))
      if (static_cast<std::size_t>(v) == k) out[s] = j;
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
  return limit_->limit_point(face_, domain_.side_point(side, t), points_);
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
  return limit_->limit_point(s.face, s.uv, points_);
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
