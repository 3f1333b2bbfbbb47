// The one interface of every patch: a domain, control points, and a
// basis with S(x) = sum_k C_k phi_k(x). phi_k may be rational; for fixed weights the surface is
// linear in the control points, which is what incremental re-evaluation relies on.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/curve/bezier_curve.hpp"
#include "core/domain/domain.hpp"
#include "core/math/jet.hpp"
#include "core/patch/surface_jet.hpp"

namespace pl {

// How a control point is drawn and what it means to the designer.
// Curve: a control point of a free curve of a scene (no patch has one; the renderer and the
// editor draw and name curve points by it). FreeInterior: a free interior point of a network GB
// face (moved by its stored offset; no patch returns it, the editor shows it).
enum class ControlPointKind { Boundary, Inner, Twin, Central, Curve, FreeInterior };

class Patch {
 public:
  virtual ~Patch() = default;
  virtual std::unique_ptr<Patch> clone() const = 0;

  // The scene-format type name ("bezier", "gb", "gregory-quad", ...).
  virtual std::string type() const = 0;
  virtual const Domain& domain() const = 0;

  std::size_t size() const { return points_.size(); }
  const std::vector<Vec3>& control_points() const { return points_; }
  const Vec3& control_point(std::size_t k) const { return points_.at(k); }
  // Overridden by patches whose points are tied together (e.g. shared GB corner blocks).
  virtual void set_control_point(std::size_t k, const Vec3& p) { points_.at(k) = p; }
  virtual ControlPointKind kind(std::size_t k) const = 0;

  // phi_k with first and second (u, v) derivatives at domain point x, for every k.
  // out.size() == size().
  virtual void basis(Vec2 x, std::span<Jet> out) const = 0;

  // S and its derivatives at x. The default sums the basis; patch types override it with
  // faster or better-conditioned forms (tests check both agree).
  virtual SurfaceJet evaluate(Vec2 x) const;

  // evaluate() at many points: out[i] = evaluate(xs[i]), out.size() == xs.size(). The default
  // loops; patch types override it with batched (SIMD across samples) forms that agree with
  // evaluate() to rounding (tests check it).
  virtual void evaluate_many(std::span<const Vec2> xs, std::span<SurfaceJet> out) const {
    for (std::size_t i = 0; i < xs.size() && i < out.size(); ++i) out[i] = evaluate(xs[i]);
  }

  // phi_k (one control point) at many domain points: the influence column of a drag.
  // The default evaluates the whole basis at every point.
  virtual void influence(std::size_t k, std::span<const Vec2> xs, std::span<Jet> out) const;

  // The curve each domain side must interpolate, parameterised like the side (side parameter t
  // is curve parameter t). Used to measure boundary deviation independently of evaluate().
  virtual std::vector<BezierCurve> boundary_curves() const = 0;

  // The point at side parameter t of the curve side `side` must interpolate. The default takes
  // it from boundary_curves(); types whose sides are not one Bézier curve (multi-span B-spline
  // or NURBS sides, composite patches) override it with their own defining curve, evaluated
  // independently of evaluate().
  virtual Vec3 boundary_point(int side, double t) const;

  // A patch that is really several surfaces (a Catmull–Clark limit surface: one per base face)
  // returns them here, each a Patch over its own domain with the same control points (in the
  // same order); scene evaluation then tessellates every piece at the full density. Empty for
  // ordinary patches.
  virtual std::vector<std::shared_ptr<Patch>> surface_pieces() const { return {}; }

 protected:
  Patch() = default;
  explicit Patch(std::vector<Vec3> points) : points_(std::move(points)) {}
  Patch(const Patch&) = default;
  Patch& operator=(const Patch&) = default;

  std::vector<Vec3> points_;
};

// The base of a concrete patch class Derived: clone() as a copy, and type() as Derived::kType,
// the class's scene-format type name, written once (its codec registers under the same).
template <class Derived>
class PatchType : public Patch {
 public:
  std::unique_ptr<Patch> clone() const final {
    return std::make_unique<Derived>(static_cast<const Derived&>(*this));
  }
  std::string type() const final { return Derived::kType; }

 protected:
  using Patch::Patch;
};

// Sum of C_k phi_k: the reference evaluation used by the default evaluate() and by tests.
SurfaceJet combine(std::span<const Vec3> points, std::span<const Jet> phi);

}  // namespace pl
