// The face schemes a comparison offers: every scheme a network face can be filled with
// (all_face_schemes, core/scene/network_edit.hpp), in that order (Auto is not one: it resolves
// to one of them per face). The CLI's
// `compare` and the editor's comparison panes take their choices from this one list, so a scheme
// added to the scene format appears in both without further work.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/scene/network.hpp"

namespace pl {

std::vector<FaceScheme> comparable_schemes();

// The scheme the scene file and the interface spell `keyword` ("gregory", "gb", ...), if it is
// one of comparable_schemes().
std::optional<FaceScheme> comparable_scheme(std::string_view keyword);

// "gregory, gb, ...": the keywords of comparable_schemes(), for messages.
std::string comparable_scheme_keywords();

// "Generalized Bezier" / "GB": a scheme's name in titles and labels, long and short (the
// keyword for a scheme without a name of its own).
std::string scheme_title(FaceScheme scheme);
std::string scheme_short_title(FaceScheme scheme);

}  // namespace pl
