#include "render/display_settings.hpp"

#include <stdexcept>

namespace pl {

bool shows_isophote_lines(const DisplaySettings& s) {
  if (s.base == BaseMode::Isophotes) return true;
  return s.isophote_lines && (s.base != BaseMode::Zebra || s.isophotes_over_zebra);
}

DisplaySettings parse_display_mode(const std::string& mode) {
  DisplaySettings s;
  std::optional<std::string> base;  // the token that set a base mode, to report conflicts
  bool isophotes = false;
  auto set_base = [&](const std::string& token, BaseMode m) {
    if (base)
      throw std::invalid_argument("mode \"" + token + "\" cannot be combined with \"" + *base +
                                  "\" (only one of shaded, zebra and the curvature maps)");
    base = token;
    s.base = m;
  };
  std::size_t start = 0;
  while (true) {
    const std::size_t plus = mode.find('+', start);
    const std::string token = mode.substr(start, plus == std::string::npos ? plus : plus - start);
    if (token == "shaded")
      set_base(token, BaseMode::Shaded);
    else if (token == "zebra")
      set_base(token, BaseMode::Zebra);
    else if (token == "mean" || token == "gaussian" || token == "kmin" || token == "kmax") {
      set_base(token, BaseMode::Curvature);
      s.curvature = token == "mean"       ? CurvatureKind::Mean
                    : token == "gaussian" ? CurvatureKind::Gaussian
                    : token == "kmin"     ? CurvatureKind::Kmin
                                          : CurvatureKind::Kmax;
    } else if (token == "isophotes")
      isophotes = true;
    else if (token == "control-net")
      s.control_net = true;
    else if (token == "network")
      s.network_curves = true;
    else if (token == "borders")
      s.borders = true;
    else if (token == "combs")
      s.combs = true;
    else
      throw std::invalid_argument(
          "unknown mode \"" + token +
          "\" (expected shaded, isophotes, zebra, mean, gaussian, kmax, kmin, control-net, "
          "network, borders or combs, combined with '+')");
    if (plus == std::string::npos) break;
    start = plus + 1;
  }
  if (isophotes) {
    if (base) {
      s.isophote_lines = true;
      s.isophotes_over_zebra = s.base == BaseMode::Zebra;
    } else {
      s.base = BaseMode::Isophotes;
    }
  }
  return s;
}

}  // namespace pl
