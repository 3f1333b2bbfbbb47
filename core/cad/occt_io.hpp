// STEP AP242 and IGES files through OpenCASCADE's XDE writers and readers (this header includes
// OCCT). The scene's name is the product name, every face carries its piece's name; units are
// millimetres (one scene unit = 1 mm).
#pragma once

#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/cad/cad_export.hpp"
#include "core/cad/occt_boundary.hpp"
#include "core/cad/occt_shape.hpp"

namespace pl {

// Writes atomically (temporary file beside the target, renamed on success). Throws DataError
// naming the target and the reason (OCCT's failures included: occt_boundary.hpp), also when the
// translation runs past the deadline.
// Free curves go in as named edges beside the sewn shape (`curves`, with their names).
void write_cad_file(const SewnShape& shape, const CadModel& model, const std::string& product,
                    CadFormat format, const std::filesystem::path& target,
                    const std::vector<std::pair<std::string, TopoDS_Edge>>& curves = {},
                    const CadDeadline& deadline = CadDeadline());

struct CadFile {
  TopoDS_Shape shape;
  std::string product;                                     // the top-level name, if any
  std::vector<std::pair<std::string, TopoDS_Face>> faces;  // every face, with its name if any
  std::vector<std::pair<std::string, TopoDS_Edge>> edges;  // every edge once, with its name if any
};
// Reads a file written by write_cad_file (or any STEP/IGES file); throws DataError naming the
// file for whatever fails, OCCT's own failures included, and once the deadline passes.
CadFile read_cad_file(const std::filesystem::path& path, CadFormat format,
                      const CadDeadline& deadline = CadDeadline());

// Silences OpenCASCADE's own console messages (transfer statistics); idempotent.
void quiet_occt();

}  // namespace pl
