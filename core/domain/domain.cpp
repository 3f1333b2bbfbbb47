#include "core/domain/domain.hpp"

namespace pl {

void snap_side_samples(const Domain& domain, Tessellation& t) {
  for (int s = 0; s < static_cast<int>(t.sides.size()); ++s)
    for (int k = 0; k <= t.density; ++k)
      t.points[t.sides[s][k]] = domain.side_point(s, double(k) / t.density);
}

}  // namespace pl
