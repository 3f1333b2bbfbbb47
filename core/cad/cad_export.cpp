#include "core/cad/cad_export.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <sstream>

#include "core/base/data_error.hpp"
#include "core/cad/cad_model.hpp"
#include "core/cad/curve_edges.hpp"
#include "core/cad/occt_io.hpp"
#include "core/cad/occt_shape.hpp"

namespace pl {

namespace {

// Edges closer than this are sewn together: far above the rounding with which pinned boundaries
// coincide (~1e-15 of the size), far below any distance between edges that must stay apart.
constexpr double kSewingTolerance = 1e-6;  // of the bounding-box diagonal

std::string format_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

}  // namespace

std::optional<CadFormat> cad_format_for(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".step" || ext == ".stp") return CadFormat::Step;
  if (ext == ".igs" || ext == ".iges") return CadFormat::Iges;
  return std::nullopt;
}

CadExportReport export_cad(const Scene& scene, const std::filesystem::path& target,
                           const CadExportOptions& options) {
  const auto format = cad_format_for(target);
  if (!format)
    throw DataError(target.string(), "", "not a STEP or IGES file name (.step .stp .igs .iges)");
  // Where the file cannot go at all, say so before the fits.
  std::error_code ec;
  if (std::filesystem::is_directory(target, ec))
    throw DataError(target.string(), "", "is a directory, not a file");
  const auto dir = target.parent_path().empty() ? std::filesystem::path(".") : target.parent_path();
  if (!std::filesystem::is_directory(dir, ec))
    throw DataError(target.string(), "", "cannot write: no directory " + dir.string());
  if (options.tolerance && !(*options.tolerance > 0 && std::isfinite(*options.tolerance)))
    throw DataError(options.source, "", "the tolerance must be a positive number");
  std::vector<CadPiece> pieces = cad_pieces(scene, options.scheme, options.source);
  if (pieces.empty() && scene.curves.empty())
    throw DataError(options.source, "", "the scene has no surface or curve to export");
  // Free curves: exact (rational) B-spline edges, named as the scene names them.
  std::vector<std::pair<std::string, TopoDS_Edge>> curves;
  for (std::size_t i = 0; i < scene.curves.size(); ++i) {
    try {
      curves.emplace_back(curve_name(scene.curves[i], i), curve_edge(scene.curves[i]));
    } catch (const std::exception& e) {
      throw DataError(options.source, "curves[" + std::to_string(i) + "]",
                      std::string("cannot export: ") + e.what());
    }
  }
  CadExportReport r;
  r.format = *format;
  r.target = target;
  r.curves = static_cast<int>(curves.size());
  CadModel model;
  SewnShape sewn;
  ShellReport shell;
  if (!pieces.empty()) {
    CadModelOptions mo;
    mo.tolerance = options.tolerance;
    try {
      model = build_cad_model(std::move(pieces), mo);
    } catch (const DataError&) {
      throw;
    } catch (const std::exception& e) {
      throw DataError(options.source, "", std::string("cannot export: ") + e.what());
    }
    for (const CadFace& f : model.faces)
      if (!f.converged) {
        // Only the position tolerance is an option; say which one failed.
        const bool position = f.position_deviation > model.tolerance;
        throw DataError(options.source, f.name,
                        "the fit did not reach the tolerance " + format_number(model.tolerance) +
                            " / " + format_number(model.normal_tolerance_deg) + " deg (deviation " +
                            format_number(f.position_deviation) + ", " +
                            format_number(f.normal_deviation_deg) + " deg)" +
                            (position ? "; try a larger --tolerance" : ""));
      }
    r.size = model.size;
    r.tolerance = model.tolerance;
    r.normal_tolerance_deg = model.normal_tolerance_deg;
    r.sewing_tolerance = kSewingTolerance * model.size;
    try {
      sewn = sew_model(model, r.sewing_tolerance);
    } catch (const std::exception& e) {
      throw DataError(options.source, "", std::string("cannot build the shape: ") + e.what());
    }
    shell = analyze_shell(sewn.shape);
  }
  std::string product = scene.name;
  if (product.empty()) product = std::filesystem::path(options.source).stem().string();
  if (product.empty()) product = target.stem().string();
  write_cad_file(sewn, model, product, *format, target, curves);

  for (const CadFace& f : model.faces) {
    CadFaceReport fr;
    fr.name = f.name;
    fr.exact = f.exact;
    fr.position_deviation = f.position_deviation;
    fr.normal_deviation_deg = f.normal_deviation_deg;
    fr.check_points = f.check_points;
    fr.control_points = f.surface.points.size();
    fr.degree_u = f.surface.degree_u;
    fr.degree_v = f.surface.degree_v;
    r.faces.push_back(fr);
  }
  r.exact_faces = model.exact_faces;
  r.fitted_faces = model.fitted_faces;
  r.shells = shell.shells;
  r.closed_shells = shell.closed_shells;
  r.solids = shell.solids;
  r.free_edges = shell.free_edges;
  r.sewn_edges = shell.sewn_edges;
  r.multiple_edges = shell.multiple_edges;
  r.max_gap = shell.max_gap;
  r.max_normal_angle_deg = shell.max_normal_angle_deg;
  return r;
}

std::string cad_report_text(const CadExportReport& r) {
  std::ostringstream os;
  if (r.faces.empty()) {
    os << "wrote " << r.curves << " curve(s) to " << r.target.string() << " ("
       << (r.format == CadFormat::Step ? "STEP AP242" : "IGES")
       << ", millimetres) as exact (rational) B-spline curves\n";
    return os.str();
  }
  os << "wrote " << r.faces.size() << " face(s) to " << r.target.string() << " ("
     << (r.format == CadFormat::Step ? "STEP AP242" : "IGES") << ", millimetres): " << r.exact_faces
     << " exact, " << r.fitted_faces << " fitted to " << format_number(r.tolerance) << " and "
     << format_number(r.normal_tolerance_deg) << " deg\n";
  if (r.curves > 0) os << "wrote " << r.curves << " curve(s) as exact (rational) B-spline curves\n";
  std::size_t width = 4;
  for (const CadFaceReport& f : r.faces) width = std::max(width, f.name.size());
  char line[256];
  std::snprintf(line, sizeof line, "  %-*s  %-6s  %9s  %9s  %7s  %s\n", int(width), "face", "kind",
                "position", "normal", "points", "degree");
  os << line;
  for (const CadFaceReport& f : r.faces) {
    std::snprintf(line, sizeof line, "  %-*s  %-6s  %9.3g  %7.4f deg %7zu  %d x %d\n", int(width),
                  f.name.c_str(), f.exact ? "exact" : "fitted", f.position_deviation,
                  f.normal_deviation_deg, f.control_points, f.degree_u, f.degree_v);
    os << line;
  }
  os << "shell: " << r.shells << " shell(s), " << r.closed_shells << " closed, " << r.solids
     << " solid(s); " << r.free_edges << " free edge(s), " << r.sewn_edges << " sewn edge(s)";
  if (r.multiple_edges) os << ", " << r.multiple_edges << " edge(s) shared by more than two faces";
  os << "; largest gap " << format_number(r.max_gap) << " (" << format_number(r.max_gap / r.size)
     << " of the size), largest normal angle across sewn edges "
     << format_number(r.max_normal_angle_deg) << " deg\n";
  return os.str();
}

}  // namespace pl
