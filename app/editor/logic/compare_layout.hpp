// The comparison's panes: how many (2, 3, 4 or 6), which face scheme each shows (any of
// comparable_schemes(), chosen in the Display panel and kept in the preferences by keyword),
// the base scheme the distance colouring and the figures measure against (one of the panes'),
// where the panes sit in the view, and what their titles say. GUI-free and unit-tested.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "app/editor/logic/view_math.hpp"
#include "core/analysis/compared_schemes.hpp"
#include "core/scene/network.hpp"

namespace pl {

inline constexpr std::array<int, 4> kComparePaneCounts{2, 3, 4, 6};
inline constexpr int kMaxComparePanes = 6;

struct CompareSetup {
  std::vector<FaceScheme> schemes;  // one per pane, left to right, top to bottom
  FaceScheme base = FaceScheme::Gregory;
  // The first pane showing the base scheme (base is always one of the panes' schemes).
  int base_pane() const;
  bool operator==(const CompareSetup&) const = default;
};

// Gregory | GB: the comparison the editor opened with before panes could be chosen.
CompareSetup default_compare_setup();

// The setup kept as keywords ("gregory,gb", "gregory"): unknown keywords and pane counts that
// are not offered give way to the default's (a preference file from another version never stops
// the editor); a base that no pane shows becomes the first pane's scheme.
CompareSetup compare_setup_from(const std::string& schemes, const std::string& base);
std::string schemes_keywords(const CompareSetup& setup);

// The same panes, `count` of them (one of kComparePaneCounts): the first ones kept, new ones
// showing the schemes not shown yet in comparable_schemes() order (then again from the start).
CompareSetup with_pane_count(CompareSetup setup, int count);

// Pane `pane` shows `scheme` instead; the base follows when it is no longer shown.
CompareSetup with_pane_scheme(CompareSetup setup, int pane, FaceScheme scheme);

// The rectangles of `count` panes in `view`: one row of up to three, else two rows (4: 2 x 2,
// 6: 3 x 2), in whole pixels that tile the view.
std::vector<ViewRect> pane_rects(const ViewRect& view, int count);

// The title of a pane showing `scheme` that fits `width` pixels, as measured by `text_width`;
// with the distance colouring a pane that is not the base says what it shows.
std::string compare_pane_title(FaceScheme scheme, bool is_base, bool difference, FaceScheme base,
                               double width,
                               const std::function<double(const std::string&)>& text_width);

}  // namespace pl
