#include "app/editor/logic/export_formats.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace pl {

namespace fs = std::filesystem;

const std::vector<ExportFormat>& export_formats() {
  static const std::vector<ExportFormat> formats = {
      {"obj", "OBJ mesh", {".obj"}, false},
      {"ply", "PLY mesh (with curvature)", {".ply"}, false},
      {"off", "OFF mesh", {".off"}, false},
      {"stl", "STL mesh", {".stl"}, false},
      {"step", "STEP (CAD surfaces)", {".step", ".stp"}, true},
      {"iges", "IGES (CAD surfaces)", {".igs", ".iges"}, true},
  };
  return formats;
}

namespace {

std::string lower_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

bool has_extension(const ExportFormat& f, const std::string& ext) {
  return std::find(f.extensions.begin(), f.extensions.end(), ext) != f.extensions.end();
}

std::string short_name(const ExportFormat& f) {
  return f.label.substr(0, f.label.find(' '));
}

}  // namespace

const ExportFormat* export_format_of(const fs::path& path) {
  const std::string ext = lower_extension(path);
  for (const ExportFormat& f : export_formats())
    if (has_extension(f, ext)) return &f;
  return nullptr;
}

std::string export_format_list() {
  std::string s;
  for (const ExportFormat& f : export_formats()) {
    s += (s.empty() ? "" : ", ") + short_name(f) + " (";
    for (std::size_t i = 0; i < f.extensions.size(); ++i) s += (i ? " " : "") + f.extensions[i];
    s += ")";
  }
  return s;
}

fs::path export_target(const fs::path& path, const ExportFormat* format) {
  if (path.filename().empty()) throw std::invalid_argument("no file name given");
  const ExportFormat* named = export_format_of(path);
  if (!format) {
    if (named) return path;
    const std::string ext = path.extension().string();
    throw std::invalid_argument((ext.empty() ? std::string("the name has no extension")
                                             : "\"" + ext + "\" is no export format") +
                                ": end the name in one of " + export_format_list() +
                                ", or choose File > Export As");
  }
  if (named == format) return path;
  if (named)
    throw std::invalid_argument("the name ends in " + path.extension().string() + " (" +
                                short_name(*named) + ") but " + short_name(*format) +
                                " was chosen: end it in " + format->extensions.front() +
                                " or leave the extension out");
  fs::path target = path;
  target += format->extensions.front();
  return target;
}

}  // namespace pl
