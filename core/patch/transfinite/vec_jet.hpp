// Vector-valued jets for the ribbon-based schemes: a SurfaceJet (a point with its exact first and
// second (u, v) derivatives) scaled by a scalar Jet, summed, and a curve composed with a
// parameter that is itself a function of (u, v). Every scheme is written with these, so its
// normals and curvatures come out exact.
#pragma once

#include "core/curve/bezier_curve.hpp"
#include "core/math/jet.hpp"
#include "core/patch/surface_jet.hpp"

namespace pl::transfinite {

inline SurfaceJet constant_jet(const Vec3& p) {
  SurfaceJet s;
  s.p = p;
  return s;
}

inline SurfaceJet& operator+=(SurfaceJet& a, const SurfaceJet& b) {
  a.p += b.p, a.su += b.su, a.sv += b.sv, a.suu += b.suu, a.suv += b.suv, a.svv += b.svv;
  return a;
}
inline SurfaceJet& operator-=(SurfaceJet& a, const SurfaceJet& b) {
  a.p -= b.p, a.su -= b.su, a.sv -= b.sv, a.suu -= b.suu, a.suv -= b.suv, a.svv -= b.svv;
  return a;
}
inline SurfaceJet operator+(SurfaceJet a, const SurfaceJet& b) {
  return a += b;
}
inline SurfaceJet operator-(SurfaceJet a, const SurfaceJet& b) {
  return a -= b;
}
inline SurfaceJet operator*(double w, SurfaceJet a) {
  a.p *= w, a.su *= w, a.sv *= w, a.suu *= w, a.suv *= w, a.svv *= w;
  return a;
}

// w S by the product rule.
inline SurfaceJet operator*(const Jet& w, const SurfaceJet& s) {
  SurfaceJet r;
  r.p = w.f * s.p;
  r.su = w.fu * s.p + w.f * s.su;
  r.sv = w.fv * s.p + w.f * s.sv;
  r.suu = w.fuu * s.p + 2 * w.fu * s.su + w.f * s.suu;
  r.suv = w.fuv * s.p + w.fu * s.sv + w.fv * s.su + w.f * s.suv;
  r.svv = w.fvv * s.p + 2 * w.fv * s.sv + w.f * s.svv;
  return r;
}

// w v for a constant vector v.
inline SurfaceJet operator*(const Jet& w, const Vec3& v) {
  SurfaceJet r;
  r.p = w.f * v, r.su = w.fu * v, r.sv = w.fv * v;
  r.suu = w.fuu * v, r.suv = w.fuv * v, r.svv = w.fvv * v;
  return r;
}

// C(t(u, v)) by the chain rule, c holding C, C' and C'' at t.f.
inline SurfaceJet compose(const CurvePoint& c, const Jet& t) {
  SurfaceJet r;
  r.p = c.p;
  r.su = t.fu * c.d1;
  r.sv = t.fv * c.d1;
  r.suu = t.fuu * c.d1 + (t.fu * t.fu) * c.d2;
  r.suv = t.fuv * c.d1 + (t.fu * t.fv) * c.d2;
  r.svv = t.fvv * c.d1 + (t.fv * t.fv) * c.d2;
  return r;
}

}  // namespace pl::transfinite
