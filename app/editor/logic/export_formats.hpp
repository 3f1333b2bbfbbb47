// The formats File > Export writes, as the user chooses them: meshes of the fine surfaces (OBJ,
// PLY, OFF, STL) and the patches as CAD surfaces (STEP, IGES), each with its file extensions. A
// format chosen in the menu decides what is written and gives a name typed without an
// extension its own; without a choice the typed extension decides, and a name that names no
// format is refused with the list of those there are. GUI-free and unit-tested.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace pl {

struct ExportFormat {
  std::string id;                       // "obj", "step": stable, for action ids and scripts
  std::string label;                    // "OBJ mesh", the menu's
  std::vector<std::string> extensions;  // lower case with the dot; the first is given to names
  bool cad = false;                     // STEP/IGES, written on a worker; else a mesh
};

// OBJ, PLY, OFF, STL, STEP, IGES, in the menu's order.
const std::vector<ExportFormat>& export_formats();
// The format whose extension `path` has (any letter case), or null.
const ExportFormat* export_format_of(const std::filesystem::path& path);
// "OBJ (.obj), PLY (.ply), ..., STEP (.step .stp), IGES (.igs .iges)": what a refusal lists.
std::string export_format_list();

// The file an export to `path` writes in `format` (null: the format the extension names):
// `path` itself when its extension is one of the format's; the format's first extension
// appended when the name has none or one that is no export format's ("part" -> "part.step",
// "part.v2" -> "part.v2.step"). Throws std::invalid_argument saying why otherwise: no format
// chosen and the extension names none, or the name ends in another format's extension.
std::filesystem::path export_target(const std::filesystem::path& path, const ExportFormat* format);

}  // namespace pl
