#include "app/editor/logic/file_listing.hpp"

#include <algorithm>
#include <cctype>
#include <system_error>

namespace pl {

namespace fs = std::filesystem;

namespace {
std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}
}  // namespace

bool has_extension(const fs::path& file, const std::vector<std::string>& extensions) {
  if (extensions.empty()) return true;
  const std::string ext = lower(file.extension().string());
  return std::any_of(extensions.begin(), extensions.end(),
                     [&](const std::string& e) { return lower(e) == ext; });
}

DirListing list_directory(const fs::path& dir, const std::vector<std::string>& extensions) {
  DirListing out;
  std::error_code ec;
  fs::directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec);
  if (ec) {
    out.error = "cannot read " + dir.string() + ": " + ec.message();
    return out;
  }
  std::vector<DirEntry> dirs, files;
  for (; it != fs::directory_iterator(); it.increment(ec)) {
    if (ec) break;
    const std::string name = it->path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    std::error_code type_ec;
    if (it->is_directory(type_ec))
      dirs.push_back({name, true});
    else if (has_extension(it->path(), extensions))
      files.push_back({name, false});
  }
  auto by_name = [](const DirEntry& a, const DirEntry& b) { return lower(a.name) < lower(b.name); };
  std::sort(dirs.begin(), dirs.end(), by_name);
  std::sort(files.begin(), files.end(), by_name);
  out.entries = std::move(dirs);
  out.entries.insert(out.entries.end(), files.begin(), files.end());
  return out;
}

fs::path resolve_typed_name(const fs::path& dir, const std::string& name,
                            const std::string& default_extension) {
  fs::path p(name);
  if (p.is_relative()) p = dir / p;
  if (!p.has_extension() && !default_extension.empty()) p += default_extension;
  return p.lexically_normal();
}

std::string extension_problem(const fs::path& file, const std::vector<std::string>& extensions) {
  if (extensions.empty() || has_extension(file, extensions)) return "";
  std::string r = "\"";
  r += file.filename().string();
  r += "\": ";
  const std::string ext = file.extension().string();
  if (ext.empty()) {
    r += "no file type";
  } else {
    r += "\"";
    r += ext;
    r += "\" is not a known type";
  }
  r += "; use ";
  for (std::size_t i = 0; i < extensions.size(); ++i) {
    if (i > 0) r += i + 1 == extensions.size() ? " or " : ", ";
    r += extensions[i];
  }
  return r;
}

}  // namespace pl
