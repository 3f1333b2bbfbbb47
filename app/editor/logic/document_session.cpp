#include "app/editor/logic/document_session.hpp"

#include "app/document/scene_file.hpp"
#include "app/document/scene_file.hpp"
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
  Scene scene = load_scene_file(file);
  if (scene_file_type(file) && !read_only(file))
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
  if (scene_file_type(doc_.path()) == SceneFileType::Gbp && !fits_gbp(doc_.scene())) return false;
  save_as(doc_.path());
  return true;
}

fs::path DocumentSession::save_as(const fs::path& typed) {
  fs::path path = typed;
  if (!path.has_extension()) path += ".json";
  if (read_only(path))
    throw DataError(path.string(), "",
                    "this folder holds the scenes shipped with PatchLab; save a copy elsewhere");
  doc_.save_as(path);  // refuses an unknown extension (save_scene_file)
  origin_.clear();
  return path;
}

DocumentSession::Suggestion DocumentSession::save_as_suggestion() const {
  Suggestion s;
  fs::path name = untitled() ? fs::path(origin_) : doc_.path().filename();
  if (!untitled()) s.dir = doc_.path().parent_path();
  const auto type = scene_file_type(name);
  if (!name.empty() && (!type || (*type == SceneFileType::Gbp && !fits_gbp(doc_.scene()))))
    name.replace_extension(".json");
  s.name = name.string();
  return s;
}

std::string DocumentSession::title() const {
  std::string t = untitled() ? std::string("untitled") : doc_.path().filename().string();
  if (untitled() && !origin_.empty()) t += " (from " + origin_ + ")";
  return t + (doc_.dirty() ? " *" : "");
}

}  // namespace pl
