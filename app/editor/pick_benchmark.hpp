// `patchlab --bench-pick [FILE]`: the cost of picking what lies under the cursor on a large
// network (a 1,536-face GB cube-sphere unless FILE is given) at the editor's rest density, in
// the same run as its baselines (testing every triangle; the same picks on a 24-face network).
// Headless: it needs no window. Prints
//   figure pick_first_ms          first pick after a load (boxes of every surface, hierarchies
//                                 of the surfaces the ray enters)
//   figure pick_ms_24_faces       mean full pick (points, curves, surfaces) over the scene
//   figure pick_ms_1536_faces     the same on the large network
//   figure pick_every_triangle_ms one ray against every triangle (the brute-force baseline)
//   figure pick_hierarchy_mb      memory of the hierarchies built by those picks
#pragma once

#include <filesystem>
#include <optional>
#include <ostream>

namespace pl {

int run_pick_benchmark(const std::optional<std::filesystem::path>& file, std::ostream& out,
                       std::ostream& err);

}  // namespace pl
