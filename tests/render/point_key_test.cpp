// The key of the control net's symbols: its rows follow the entries, its symbols are drawn by the
// scene's own point shader (read back: an editable point's middle is its kind's colour, a derived
// one's is the light fill), and the full key matches its golden image (the one the help shows).
#include "render/point_key.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "golden.hpp"
#include "render/palette.hpp"
#include "render_test_util.hpp"

namespace pl {
namespace {

TEST(PointKey, RowsFollowTheEntries) {
  PointKeyEntries e;
  EXPECT_TRUE(point_key_layout(e, 1, 1).rows.empty());
  e.point_styles = (1u << point_style_tag(ControlPointKind::Boundary, PointRole::Editable)) |
                   (1u << point_style_tag(ControlPointKind::Twin, PointRole::Derived));
  e.arrow_kinds = 1u << int(ArrowKind::Twist);
  const PointKeyLayout k = point_key_layout(e, 1, 1);
  ASSERT_EQ(k.rows.size(), 3u);
  EXPECT_EQ(k.rows[0].label, "boundary");
  EXPECT_EQ(k.rows[1].label, "twin, derived");
  EXPECT_EQ(k.rows[2].label, "twist");
  // Six kinds editable, four derived (curve points and a GB face's free points are never
  // derived), two arrows.
  EXPECT_EQ(point_key_layout(PointKeyEntries::all(), 1, 1).rows.size(), 12u);
  const auto rows = point_key_layout(PointKeyEntries::all(), 1, 1).rows;
  EXPECT_EQ(rows[4].label, "curve");
  EXPECT_EQ(rows[4].kind, int(ControlPointKind::Curve));
  // Sizes follow the text scale.
  const PointKeyLayout big = point_key_layout(e, 3, 1);
  EXPECT_GT(big.width, 2 * k.width);
}

TEST(PointKey, SymbolsAreTheScenesAndTheKeyMatchesItsGolden) {
  PATCHLAB_REQUIRE_GL();
  SceneRenderer renderer;
  const PointKeyLayout k = point_key_layout(PointKeyEntries::all(), 1.5, 1.5);
  const Image key = render_point_key(renderer, k);
  ASSERT_EQ(key.width, k.width);
  ASSERT_EQ(key.height, k.height);
  const int x = k.pad + k.symbol_width / 2;
  for (std::size_t i = 0; i < k.rows.size(); ++i) {
    const auto& row = k.rows[i];
    if (row.kind < 0) continue;
    const int y = static_cast<int>(std::lround(k.pad + (i + 0.5) * k.row_height));
    const uint8_t* p = key.at(x, y);
    const Rgb& expected = row.role == PointRole::Editable ? palette::kPointKinds[row.kind]
                                                          : palette::kDerivedPointFill;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(p[c], expected[c] * 255, 4) << row.label;
  }
  test::compare_with_golden("point-key", key);
}

}  // namespace
}  // namespace pl
