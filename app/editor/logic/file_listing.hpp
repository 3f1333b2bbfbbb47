// The in-app file browser's model: one directory's entries, folders first, filtered by
// extension. GUI-free and unit-tested; the ImGui widget only draws it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace pl {

struct DirEntry {
  std::string name;
  bool directory = false;
};

struct DirListing {
  std::vector<DirEntry> entries;  // directories (sorted), then matching files (sorted)
  std::string error;              // non-empty when the directory could not be read
};

// Lists `dir`, skipping hidden entries; files only when their extension (case-insensitive, with
// the dot, e.g. ".json") is in `extensions` (empty: every file).
DirListing list_directory(const std::filesystem::path& dir,
                          const std::vector<std::string>& extensions);

bool has_extension(const std::filesystem::path& file, const std::vector<std::string>& extensions);

// What a typed name means in `dir`: absolute names are kept, relative ones joined to dir; when
// the name has no extension the default one is appended (Save As "part" -> "part.json").
std::filesystem::path resolve_typed_name(const std::filesystem::path& dir, const std::string& name,
                                         const std::string& default_extension);

// Why the browser does not accept `file` (a resolved typed name): its extension is not one of
// `extensions` ("part.jsonn" in Save As: a file Open would never list). Empty when accepted or
// when any extension is (no extensions given).
std::string extension_problem(const std::filesystem::path& file,
                              const std::vector<std::string>& extensions);

}  // namespace pl
