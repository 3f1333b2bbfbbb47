// Exact differential geometry of a surface point from its first and second derivatives.
//
// Conventions: the unit normal is n = Su x Sv / |Su x Sv|. The second fundamental form uses
// that normal (L = Suu.n, M = Suv.n, N = Svv.n), so the mean curvature H = (k_min + k_max) / 2 is
// positive where the surface bends towards n (a sphere with outward normal has H = -1/R,
// K = 1/R^2).
#pragma once

#include <cstdint>
#include <span>

#include "core/patch/surface_jet.hpp"

namespace pl {

enum class GeometryStatus : uint8_t {
  Regular,   // normal and curvatures are exact
  Singular,  // Su x Sv vanishes (degenerate parameterisation, e.g. a collapsed corner):
             // the evaluator fills normal/curvature from the limit towards the domain interior
};

struct SurfaceGeometry {
  Vec3 normal{0};
  double gaussian = 0, mean = 0, kmin = 0, kmax = 0;
  GeometryStatus status = GeometryStatus::Singular;
};

struct FundamentalForms {
  double E, F, G;  // first
  double L, M, N;  // second, with the unit normal above
};

// Normal and curvatures; status Singular (and zeros, never NaN) where the normal is undefined.
SurfaceGeometry differential_geometry(const SurfaceJet& s);

// differential_geometry of every sample (out[i] from s[i]), several samples per SIMD lane block;
// the same numbers as the one-sample form.
void differential_geometry_many(std::span<const SurfaceJet> s, std::span<SurfaceGeometry> out);
// The same for the samples listed in index only: out[index[i]] from s[index[i]].
void differential_geometry_many(std::span<const SurfaceJet> s, std::span<const uint32_t> index,
                                std::span<SurfaceGeometry> out);

// Fundamental forms; only meaningful where differential_geometry() reports Regular.
FundamentalForms fundamental_forms(const SurfaceJet& s);

struct PrincipalDirections {
  Vec3 dir_min{0}, dir_max{0};  // unit tangent vectors of k_min and k_max (arbitrary at umbilics)
};
PrincipalDirections principal_directions(const SurfaceJet& s);

}  // namespace pl
