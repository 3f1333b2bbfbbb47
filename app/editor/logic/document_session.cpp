#include "app/editor/logic/document_session.hpp"

#include "app/cli/load_input.hpp"
#include "core/base/data_error.hpp"

namespace pl {

namespace fs = std::filesystem;

namespace {

fs::path normalised(const fs::path& p) {
  std::error_code ec;
  fs::path r = fs::weakly_canonical(fs::absolute(p, ec), ec);
  return ec ? fs::absolute(p).lexically_normal() : r;
}

}  // namespace

bool is_inside(const fs::path& file, const fs::path& dir) {
  const fs::path f = normalised(file), d = normalised(dir);
  const fs::path rel = f.lexically_relative(d);
  return !rel.empty() && *rel.begin() != ".." && rel.is_relative();
}

DocumentSession::DocumentSession(std::vector<fs::path> read_only_dirs)
    : read_only_dirs_(std::move(read_only_dirs)) {}

bool DocumentSession::read_only(const fs::path& path) const {
  for (const fs::path& d : read_only_dirs_)
    if (is_inside(path, d)) return true;
  return false;
}

void DocumentSession::open(const fs::path& file) {
  Scene scene = load_input(file);
  const std::string ext = file.extension().string();
  const bool is_scene = ext == ".json" || ext == ".JSON";
  if (is_scene && !read_only(file))
    replace(Document(std::move(scene), file));
  else
    replace(Document(std::move(scene)), file.filename().string());
}

void DocumentSession::new_scene() {
  Scene scene;
  scene.name = "untitled";
  scene.network = Network{};
  replace(Document(std::move(scene)));
}

void DocumentSession::replace(Document doc, std::string origin) {
  doc_ = std::move(doc);
  origin_ = std::move(origin);
  ++serial_;
}

bool DocumentSession::save() {
  if (untitled()) return false;
  save_as(doc_.path());
  return true;
}

void DocumentSession::save_as(const fs::path& path) {
  if (read_only(path))
    throw DataError(path.string(), "",
                    "this folder holds the scenes shipped with PatchLab; save a copy elsewhere");
  doc_.save_as(path);
  origin_.clear();
}

std::string DocumentSession::title() const {
  std::string t = untitled() ? std::string("untitled") : doc_.path().filename().string();
  if (untitled() && !origin_.empty()) t += " (from " + origin_ + ")";
  return t + (doc_.dirty() ? " *" : "");
}

}  // namespace pl
