// Catmull-Clark limit surfaces as patches (catmull_clark_limit.hpp does the OpenSubdiv work).
//
// CatmullClarkFacePatch: the limit surface over one ptex face (a base quad, or one of the n
// sub-quads of an n-gon), domain [0,1]^2 = the ptex face's (u, v). Its control points are all base
// vertices; only the face's neighbourhood has non-zero weights, so drags are sparse.
//
// CatmullClarkPatch: the whole surface as one scene entry ("catmull-clark"). Scene evaluation
// draws it as its surface_pieces(): one CatmullClarkFacePatch per base face, each at the full
// density (one per ptex face: n for an n-gon). As a Patch by itself it is an atlas (ptex face f
// covers the strip u in [f/F, (f+1)/F] of [0,1]^2) so that tools taking one Patch still work
// on it.
#pragma once

#include <memory>

#include "core/domain/unit_square.hpp"
#include "core/patch/catmull_clark_limit.hpp"
#include "core/patch/patch.hpp"

namespace pl {

class CatmullClarkFacePatch final : public Patch {
 public:
  CatmullClarkFacePatch(std::shared_ptr<const CatmullClarkLimit> limit, int face,
                        std::vector<Vec3> vertices);

  std::unique_ptr<Patch> clone() const override {
    return std::make_unique<CatmullClarkFacePatch>(*this);
  }
  std::string type() const override { return "catmull-clark-face"; }
  const Domain& domain() const override { return domain_; }
  ControlPointKind kind(std::size_t k) const override;
  void basis(Vec2 x, std::span<Jet> out) const override;
  // O(1) per sample: the 16 or 20 patch points of the sample's limit patch, placed once.
  SurfaceJet evaluate(Vec2 x) const override;
  void influence(std::size_t k, std::span<const Vec2> xs, std::span<Jet> out) const override;
  // Re-places the patch points whose stencil holds vertex k.
  void set_control_point(std::size_t k, const Vec3& p) override;
  // Exact for a regular boundary face side (a uniform cubic B-spline segment in Bézier form);
  // otherwise the Bézier curve on the side's limit points at t = 0, 1/3, 2/3, 1 interpolated
  // (the limit side of an irregular face is not one polynomial).
  std::vector<BezierCurve> boundary_curves() const override;
  // The limit surface on the side through OpenSubdiv's limit stencils (independent of
  // evaluate()), exact for every face.
  Vec3 boundary_point(int side, double t) const override;

  int face() const { return face_; }  // the ptex face index (= base face for quad meshes)

 private:
  std::shared_ptr<const CatmullClarkLimit> limit_;
  int face_;                   // ptex face
  std::vector<char> support_;  // vertices with a non-zero stencil weight on this face
  std::vector<Vec3> local_;    // positions of limit_->face_points(face_)
  UnitSquareDomain domain_;
};

class CatmullClarkPatch final : public Patch {
 public:
  static constexpr const char* kType = "catmull-clark";  // the scene-format type name
  // Throws std::invalid_argument for a mesh CatmullClarkLimit refuses.
  CatmullClarkPatch(std::vector<Vec3> vertices, std::vector<std::vector<int>> faces);

  std::unique_ptr<Patch> clone() const override {
    return std::make_unique<CatmullClarkPatch>(*this);
  }
  std::string type() const override { return kType; }
  const Domain& domain() const override { return domain_; }
  ControlPointKind kind(std::size_t k) const override;
  void basis(Vec2 x, std::span<Jet> out) const override;
  SurfaceJet evaluate(Vec2 x) const override;
  // The atlas's sides cross many faces: the Bézier curve on the limit points at the face
  // breaks (not exact; the interface has no piecewise curve).
  std::vector<BezierCurve> boundary_curves() const override;
  // The limit side through OpenSubdiv's limit stencils on the face the side parameter falls in.
  Vec3 boundary_point(int side, double t) const override;
  // One CatmullClarkFacePatch per ptex face (face order; n per n-gon), each over its own unit
  // square with all control vertices: scenes tessellate every face at the full density.
  std::vector<std::shared_ptr<Patch>> surface_pieces() const override;

  const CatmullClarkLimit& limit() const { return *limit_; }
  std::vector<std::unique_ptr<CatmullClarkFacePatch>> face_patches() const;

 private:
  std::shared_ptr<const CatmullClarkLimit> limit_;
  UnitSquareDomain domain_;
};

}  // namespace pl
