// The in-app file dialog (ImGui 1.86 has none): a modal that lists one directory (folders, then
// files matching the filter), lets the user walk up and down, click a file or type a name, and
// reports the chosen path. The listing itself is GUI-free (logic/file_listing.hpp).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/editor/logic/file_listing.hpp"

namespace pl {

class FileBrowser {
 public:
  // Opens the dialog on the next draw(). `action` is the button label ("Open", "Save", ...).
  void open(const std::string& title, const std::string& action, std::filesystem::path dir,
            std::vector<std::string> extensions, std::string default_extension,
            std::string name = "");
  // Draws the modal while open; returns the chosen path once (when the user confirms).
  std::optional<std::filesystem::path> draw();
  const std::filesystem::path& directory() const { return dir_; }

 private:
  void refresh();
  std::string title_, action_, default_extension_;
  std::filesystem::path dir_;
  std::vector<std::string> extensions_;
  DirListing listing_;
  char name_[512] = {};
  std::string problem_;   // why the typed name was refused, shown until the next try
  bool refocus_ = false;  // the name field takes the keys again on the next frame
  bool open_request_ = false;
  int selected_ = -1;
};

}  // namespace pl
