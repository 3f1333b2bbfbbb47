// Jet: a scalar function of (u, v) carried with its gradient and Hessian (forward-mode
// automatic differentiation to second order). Rational blending functions (Gregory twins,
// GB weights) are written once with Jets and their exact derivatives come for free.
#pragma once

#include <cmath>

namespace pl {

struct Jet {
  double f = 0, fu = 0, fv = 0, fuu = 0, fuv = 0, fvv = 0;

  constexpr Jet() = default;
  constexpr Jet(double value) : f(value) {}  // NOLINT: constants promote to jets
  constexpr Jet(double f_, double fu_, double fv_, double fuu_, double fuv_, double fvv_)
      : f(f_), fu(fu_), fv(fv_), fuu(fuu_), fuv(fuv_), fvv(fvv_) {}

  static constexpr Jet u(double value) { return {value, 1, 0, 0, 0, 0}; }
  static constexpr Jet v(double value) { return {value, 0, 1, 0, 0, 0}; }

  constexpr Jet& operator+=(const Jet& b) {
    f += b.f, fu += b.fu, fv += b.fv, fuu += b.fuu, fuv += b.fuv, fvv += b.fvv;
    return *this;
  }
  constexpr Jet& operator-=(const Jet& b) {
    f -= b.f, fu -= b.fu, fv -= b.fv, fuu -= b.fuu, fuv -= b.fuv, fvv -= b.fvv;
    return *this;
  }
  constexpr Jet& operator*=(double s) {
    f *= s, fu *= s, fv *= s, fuu *= s, fuv *= s, fvv *= s;
    return *this;
  }
  bool is_zero() const { return f == 0 && fu == 0 && fv == 0 && fuu == 0 && fuv == 0 && fvv == 0; }
};

constexpr Jet operator-(const Jet& a) {
  return {-a.f, -a.fu, -a.fv, -a.fuu, -a.fuv, -a.fvv};
}
constexpr Jet operator+(Jet a, const Jet& b) {
  return a += b;
}
constexpr Jet operator-(Jet a, const Jet& b) {
  return a -= b;
}
constexpr Jet operator*(Jet a, double s) {
  return a *= s;
}
constexpr Jet operator*(double s, Jet a) {
  return a *= s;
}

// The product and chain rules as templates over the jet type: Jet here, and JetLanes
// (core/math/lanes.hpp) runs the very same operations on SIMD lanes, one sample per lane.
template <class J>
[[gnu::always_inline]] constexpr J jet_product(const J& a, const J& b) {
  return {a.f * b.f,
          a.fu * b.f + a.f * b.fu,
          a.fv * b.f + a.f * b.fv,
          a.fuu * b.f + 2 * a.fu * b.fu + a.f * b.fuu,
          a.fuv * b.f + a.fu * b.fv + a.fv * b.fu + a.f * b.fuv,
          a.fvv * b.f + 2 * a.fv * b.fv + a.f * b.fvv};
}

// a * l for an l linear in (u, v) (zero Hessian, which is not read).
template <class J, class L>
[[gnu::always_inline]] constexpr J jet_times_linear(const J& a, const L& l) {
  return {a.f * l.f,
          a.fu * l.f + a.f * l.fu,
          a.fv * l.f + a.f * l.fv,
          a.fuu * l.f + 2 * a.fu * l.fu,
          a.fuv * l.f + a.fu * l.fv + a.fv * l.fu,
          a.fvv * l.f + 2 * a.fv * l.fv};
}

template <class J, class D>
[[gnu::always_inline]] constexpr J jet_chain(const J& a, const D& d0, const D& d1, const D& d2) {
  return {d0,
          d1 * a.fu,
          d1 * a.fv,
          d1 * a.fuu + d2 * a.fu * a.fu,
          d1 * a.fuv + d2 * a.fu * a.fv,
          d1 * a.fvv + d2 * a.fv * a.fv};
}

constexpr Jet operator*(const Jet& a, const Jet& b) {
  return jet_product(a, b);
}

// The names the lane forms (core/math/lanes.hpp) carry, for Jet: code templated over the jet type
// (GB blends, polygon parameters) calls these and runs the same operations on either.
constexpr Jet product(const Jet& a, const Jet& b) {
  return jet_product(a, b);
}
constexpr Jet sum(const Jet& a, const Jet& b) {
  return a + b;
}
constexpr Jet difference(const Jet& a, const Jet& b) {
  return a - b;
}
constexpr Jet scaled(const Jet& a, double s) {
  return a * s;
}
constexpr void add_to(Jet& a, const Jet& b) {
  a += b;
}

// Applies a scalar function g with g(x) = d0, g'(x) = d1, g''(x) = d2 by the chain rule.
constexpr Jet chain(const Jet& a, double d0, double d1, double d2) {
  return jet_chain(a, d0, d1, d2);
}

inline Jet reciprocal(const Jet& a) {
  const double r = 1.0 / a.f;
  return chain(a, r, -r * r, 2 * r * r * r);
}
inline Jet operator/(const Jet& a, const Jet& b) {
  return a * reciprocal(b);
}
inline Jet operator/(const Jet& a, double s) {
  return a * (1.0 / s);
}
inline Jet operator/(double s, const Jet& b) {
  return s * reciprocal(b);
}
inline Jet sqrt(const Jet& a) {
  const double r = std::sqrt(a.f);
  return chain(a, r, 0.5 / r, -0.25 / (r * a.f));
}
// Integer power by repeated multiplication; p >= 0.
inline Jet pow(const Jet& a, int p) {
  Jet r(1.0);
  for (int i = 0; i < p; ++i) r = r * a;
  return r;
}

}  // namespace pl
