#include "app/editor/logic/compare_layout.hpp"

#include <algorithm>
#include <cmath>

#include "core/analysis/compared_schemes.hpp"
#include "core/scene/network_edit.hpp"

namespace pl {

int CompareSetup::base_pane() const {
  for (std::size_t i = 0; i < schemes.size(); ++i)
    if (schemes[i] == base) return int(i);
  return 0;
}

CompareSetup default_compare_setup() {
  return {{FaceScheme::Gregory, FaceScheme::GB}, FaceScheme::Gregory};
}

CompareSetup compare_setup_from(const std::string& schemes, const std::string& base) {
  CompareSetup s;
  std::size_t start = 0;
  while (start <= schemes.size()) {
    const std::size_t comma = std::min(schemes.find(',', start), schemes.size());
    const auto scheme = comparable_scheme(schemes.substr(start, comma - start));
    if (!scheme) return default_compare_setup();
    s.schemes.push_back(*scheme);
    start = comma + 1;
  }
  if (std::find(kComparePaneCounts.begin(), kComparePaneCounts.end(), int(s.schemes.size())) ==
      kComparePaneCounts.end())
    return default_compare_setup();
  const auto b = comparable_scheme(base);
  s.base = b && std::find(s.schemes.begin(), s.schemes.end(), *b) != s.schemes.end()
               ? *b
               : s.schemes.front();
  return s;
}

std::string schemes_keywords(const CompareSetup& setup) {
  std::string out;
  for (FaceScheme s : setup.schemes) {
    if (!out.empty()) out += ",";
    out += scheme_keyword(s);
  }
  return out;
}

CompareSetup with_pane_count(CompareSetup setup, int count) {
  if (std::find(kComparePaneCounts.begin(), kComparePaneCounts.end(), count) ==
      kComparePaneCounts.end())
    return setup;
  if (int(setup.schemes.size()) > count) setup.schemes.resize(count);
  const std::vector<FaceScheme> all = comparable_schemes();
  std::vector<FaceScheme> unshown;
  for (FaceScheme s : all)
    if (std::find(setup.schemes.begin(), setup.schemes.end(), s) == setup.schemes.end())
      unshown.push_back(s);
  for (std::size_t k = 0; int(setup.schemes.size()) < count; ++k)
    setup.schemes.push_back(k < unshown.size() ? unshown[k]
                                               : all[(k - unshown.size()) % all.size()]);
  if (std::find(setup.schemes.begin(), setup.schemes.end(), setup.base) == setup.schemes.end())
    setup.base = setup.schemes.front();
  return setup;
}

CompareSetup with_pane_scheme(CompareSetup setup, int pane, FaceScheme scheme) {
  if (pane < 0 || pane >= int(setup.schemes.size())) return setup;
  setup.schemes[pane] = scheme;
  if (std::find(setup.schemes.begin(), setup.schemes.end(), setup.base) == setup.schemes.end())
    setup.base = scheme;
  return setup;
}

std::vector<ViewRect> pane_rects(const ViewRect& r, int count) {
  if (count <= 1) return {r};
  const int rows = count <= 3 ? 1 : 2;
  const int cols = (count + rows - 1) / rows;
  std::vector<ViewRect> out;
  for (int k = 0; k < count; ++k) {
    const int i = k % cols, j = k / cols;
    const double x0 = std::floor(r.x + r.width * i / cols),
                 x1 = i + 1 == cols ? r.x + r.width : std::floor(r.x + r.width * (i + 1) / cols);
    const double y0 = std::floor(r.y + r.height * j / rows),
                 y1 = j + 1 == rows ? r.y + r.height : std::floor(r.y + r.height * (j + 1) / rows);
    out.push_back({x0, y0, x1 - x0, y1 - y0});
  }
  return out;
}

std::string compare_pane_title(FaceScheme scheme, bool is_base, bool difference, FaceScheme base,
                               double width,
                               const std::function<double(const std::string&)>& text_width) {
  std::vector<std::string> titles;
  if (difference && !is_base)
    titles = {scheme_title(scheme) + ", coloured by distance to " + scheme_title(base),
              scheme_short_title(scheme) + ": distance to " + scheme_short_title(base),
              scheme_short_title(scheme)};
  else if (difference)
    titles = {scheme_title(scheme) + " (base)", scheme_short_title(scheme) + " (base)",
              scheme_short_title(scheme)};
  else
    titles = {scheme_title(scheme), scheme_short_title(scheme)};
  for (const std::string& t : titles)
    if (text_width(t) <= width) return t;
  return titles.back();
}

}  // namespace pl
