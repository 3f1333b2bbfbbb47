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

  // A scene (.json) or GB patch (.gbp) keeps its path unless it is a shipped sample (then it is
  // an untitled copy), so Save writes a .gbp back as a .gbp. Throws DataError; the current
  // document stays on failure.
  void open(const std::filesystem::path& file);
  // An empty scene: a network without vertices, untitled.
  void new_scene();
  // Any document (the editor's benchmark scenes); `origin` names where an untitled one came from.
  void replace(Document doc, std::string origin = "");

  // Writes the document to its path and returns true, or returns false without writing when it
  // has none yet (untitled) or its file type can no longer hold it (a .gbp scene that gained a
  // network): the caller asks for a path (save_as_suggestion) and calls save_as. Throws
  // DataError.
  bool save();
  // Writes the document to `path` and makes that its file; returns the path written. A name
  // without an extension gets ".json"; any extension but .json and .gbp (scene_file.hpp) is
  // refused, as is a read-only folder: DataError, nothing written.
  std::filesystem::path save_as(const std::filesystem::path& path);

  // Where Save As starts: the document's folder (empty when untitled: the caller chooses) and
  // a name, the document's own or its origin's, with ".json" when its type cannot hold it.
  struct Suggestion {
    std::filesystem::path dir;
    std::string name;
  };
  Suggestion save_as_suggestion() const;

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
