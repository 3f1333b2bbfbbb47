#include "core/analysis/compared_schemes.hpp"

#include "core/scene/network_edit.hpp"

namespace pl {

std::vector<FaceScheme> comparable_schemes() {
  const auto all = all_face_schemes();
  return {all.begin(), all.end()};
}

std::optional<FaceScheme> comparable_scheme(std::string_view keyword) {
  const auto s = parse_scheme_keyword(keyword);
  if (s && *s != FaceScheme::Auto) return s;
  return std::nullopt;
}

std::string comparable_scheme_keywords() {
  return face_scheme_keywords();
}

namespace {
struct Titles {
  const char *keyword, *title, *short_title;
};
// The schemes whose names read better than their keywords; any other scheme is titled by its
// keyword.
constexpr Titles kTitles[] = {
    {"gregory", "Gregory", "Gregory"},
    {"gb", "Generalized Bezier", "GB"},
    {"side-based", "Side-based (Kato)", "side-based"},
    {"corner-based", "Corner-based (Charrot-Gregory)", "corner-based"},
    {"generalized-coons", "Generalized Coons", "gen. Coons"},
    {"composite-ribbon", "Composite ribbon", "composite"},
    {"midpoint", "Midpoint", "midpoint"},
    {"midpoint-coons", "Midpoint Coons", "midpoint Coons"},
    {"elastic", "Elastic (Sabin)", "elastic"},
};
const Titles* titles_of(FaceScheme s) {
  const std::string k = scheme_keyword(s);
  for (const Titles& t : kTitles)
    if (k == t.keyword) return &t;
  return nullptr;
}
}  // namespace

std::string scheme_title(FaceScheme s) {
  const Titles* t = titles_of(s);
  return t ? t->title : scheme_keyword(s);
}

std::string scheme_short_title(FaceScheme s) {
  const Titles* t = titles_of(s);
  return t ? t->short_title : scheme_keyword(s);
}

}  // namespace pl
