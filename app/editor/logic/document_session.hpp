// The document the editor works on and the rules for where it may be written. Scenes shipped
// with PatchLab (the assets folder next to the sources, or found next to the executable) are
// samples: opening one, or starting with no file (the default scene), gives an untitled copy,
// so Save asks for a path, and no save is ever written into those folders. File > New is an
// empty network. Replacing the document bumps serial(), which tells the editor's other parts
// to drop what they held about the old one. GUI-free and unit-tested.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "app/document/document.hpp"

namespace pl {

// True when `file` lies inside `dir` (both made absolute and normalised, symlinks resolved
// where they exist).
bool is_inside(const std::filesystem::path& file, const std::filesystem::path& dir);

class DocumentSession {
 public:
  explicit DocumentSession(std::vector<std::filesystem::path> read_only_dirs = {});

  Document& doc() { return doc_; }
  const Document& doc() const { return doc_; }

  // A scene (.json) keeps its path unless it is a shipped sample; a .gbp is imported as an
  // untitled scene. Throws DataError; the current document stays on failure.
  void open(const std::filesystem::path& file);
  // An empty scene: a network without vertices, untitled.
  void new_scene();
  // Any document (the editor's benchmark scenes); `origin` names where an untitled one came from.
  void replace(Document doc, std::string origin = "");

  // Writes the document to its path and returns true, or returns false without writing when it
  // has none yet (untitled): the caller asks for one and calls save_as. Throws DataError.
  bool save();
  // Throws DataError, writing nothing, when `path` is in a read-only folder.
  void save_as(const std::filesystem::path& path);

  bool read_only(const std::filesystem::path& path) const;
  bool untitled() const { return doc_.path().empty(); }
  // What the window title shows: "part.json", "untitled (from default.json)", with " *" when
  // there are unsaved changes.
  std::string title() const;
  uint64_t serial() const { return serial_; }

 private:
  std::vector<std::filesystem::path> read_only_dirs_;
  Document doc_;
  std::string origin_;
  uint64_t serial_ = 0;
};

}  // namespace pl
