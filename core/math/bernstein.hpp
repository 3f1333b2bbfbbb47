// Bernstein polynomials B_i^n(t) = C(n,i) t^i (1-t)^(n-i), with derivatives.
#pragma once

#include <span>
#include <vector>

#include "core/math/jet.hpp"

namespace pl {

double binomial(int n, int k);

// All n+1 Bernstein values of degree n at t (de Casteljau-like triangle, stable on [0,1]).
void bernstein_all(int n, double t, std::span<double> out);

// Values, first and second derivatives of all n+1 polynomials: d0[i], d1[i], d2[i].
void bernstein_all_d2(int n, double t, std::span<double> d0, std::span<double> d1,
                      std::span<double> d2);

// One Bernstein polynomial composed with a jet argument: B_i^n(t(u,v)) with exact derivatives.
Jet bernstein(int n, int i, const Jet& t);

}  // namespace pl
