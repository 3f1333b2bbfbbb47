// A parameter domain: the unit square, the unit triangle or a polygon. It knows its sides and
// how to tessellate itself; it knows nothing about patches.
#pragma once

#include <memory>
#include <string>

#include "core/domain/tessellation.hpp"

namespace pl {

class Domain {
 public:
  virtual ~Domain() = default;
  virtual int side_count() const = 0;
  // Point of side i at side parameter t in [0,1] (t = 0 at the side's start vertex).
  virtual Vec2 side_point(int side, double t) const = 0;
  // A point well inside the domain; singular samples are approached from its direction.
  virtual Vec2 interior_point() const = 0;
  // Identifies the tessellation: two domains with equal keys tessellate identically.
  virtual std::string key() const = 0;
  // Samples with density + 1 points on every side at equal side parameters. density >= 1.
  virtual Tessellation tessellate(int density) const = 0;
};

// Sets every side sample to exactly side_point(side, k / density): a sample computed as
// (n - k) / n can differ by one ulp from 1 - k / n, and neighbouring patches must sample their
// shared edge at the very same curve parameters. Every tessellate() ends with this.
void snap_side_samples(const Domain& domain, Tessellation& t);

}  // namespace pl
