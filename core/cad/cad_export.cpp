#include "core/cad/cad_export.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "core/base/data_error.hpp"
#include "core/cad/cad_model.hpp"
#include "core/cad/curve_edges.hpp"
#include "core/cad/occt_boundary.hpp"
#include "core/cad/occt_io.hpp"
#include "core/cad/occt_shape.hpp"
#include "core/io/json_node.hpp"  // short_number

namespace pl {

namespace {

// Edges closer than this are sewn together: far above the rounding with which pinned boundaries
// coincide (~1e-15 of the size), far below any distance between edges that must stay apart.
constexpr double kSewingTolerance = 1e-6;  // of the bounding-box diagonal

std::string format_number(double v) {
  return short_number(v);
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

double scene_control_size(const Scene& scene) {
  Vec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  auto add = [&](const Vec3& p) { lo = glm::min(lo, p), hi = glm::max(hi, p); };
  if (scene.network) {
    for (const Vec3& p : scene.network->vertices) add(p);
    for (const NetworkEdge& e : scene.network->edges)
      for (const Vec3& h : e.handles) add(h);
  }
  for (const ScenePatch& p : scene.patches)
    if (p.patch)
      for (const Vec3& q : p.patch->control_points()) add(q);
  for (const SceneCurve& c : scene.curves)
    for (const Vec3& q : spline_form(c).points) add(q);
  return lo.x <= hi.x ? glm::length(hi - lo) : 0.0;
}

namespace {

CadExportReport export_cad_unguarded(const Scene& scene, const std::filesystem::path& target,
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
  // Scale: OCCT's tolerances are absolute, so the size is checked before anything reaches them
  // (or the fitter, whose default tolerance follows the size).
  const double size = scene_control_size(scene);
  if (size > 0 && !(size >= kMinCadSize && size <= kMaxCadSize))
    throw DataError(options.source, "",
                    "the scene's size " + short_number(size) +
                        " (the diagonal of its control points' bounding box) is outside the range "
                        "STEP and IGES export supports, " +
                        short_number(kMinCadSize) + " to " + short_number(kMaxCadSize) +
                        " (millimetres); scale the scene into it");
  const CadDeadline deadline(options.time_limit_s);
  const auto fit_deadline =
      options.time_limit_s > 0 && std::isfinite(options.time_limit_s)
          ? std::chrono::steady_clock::now() +
                std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                    std::chrono::duration<double>(options.time_limit_s))
          : std::chrono::steady_clock::time_point::max();
  std::vector<CadPiece> pieces = cad_pieces(scene, options.scheme, options.source);
  if (pieces.empty() && scene.curves.empty())
    throw DataError(options.source, "", "the scene has no surface or curve to export");
  if (pieces.size() > kMaxCadFaces)
    throw DataError(options.source, "",
                    "the scene makes " + std::to_string(pieces.size()) +
                        " faces; STEP and IGES export supports at most " +
                        std::to_string(kMaxCadFaces));
  // Free curves: exact (rational) B-spline edges, named as the scene names them; a curve broken
  // at a knot of multiplicity degree + 1 is one edge per piece, NAME.1, NAME.2, ...
  std::vector<std::pair<std::string, TopoDS_Edge>> curves;
  int curve_pieces_written = 0;
  for (std::size_t i = 0; i < scene.curves.size(); ++i) {
    const std::string name = curve_name(scene.curves[i], i);
    const std::vector<TopoDS_Edge> edges =
        occt_call({options.source, "curves[" + std::to_string(i) + "]"}, "cannot export",
                  [&] { return curve_edges(scene.curves[i]); });
    for (std::size_t k = 0; k < edges.size(); ++k)
      curves.emplace_back(edges.size() == 1 ? name : name + "." + std::to_string(k + 1), edges[k]);
    curve_pieces_written += edges.size() > 1 ? 1 : 0;
  }
  CadExportReport r;
  r.format = *format;
  r.target = target;
  r.curves = static_cast<int>(scene.curves.size());
  r.broken_curves = curve_pieces_written;
  r.curve_edges = static_cast<int>(curves.size());
  CadModel model;
  SewnShape sewn;
  ShellReport shell;
  if (!pieces.empty()) {
    CadModelOptions mo;
    mo.tolerance = options.tolerance;
    if (options.max_fit_work) mo.max_work = options.max_fit_work;
    mo.deadline = fit_deadline;
    try {
      model = build_cad_model(std::move(pieces), mo);
    } catch (const DataError&) {
      throw;
    } catch (const std::exception& e) {
      throw DataError(options.source, "", std::string("cannot export: ") + e.what());
    }
    FitTolerance ft;
    ft.max_work = mo.max_work;
    ft.max_shared_work = mo.max_total_work;
    ft.max_spans = mo.max_spans;
    // The face to name: the first that failed on its own account (a face stopped because the
    // export's shared bound was spent, possibly by another's failure, only if there is none).
    const CadFace* failed = nullptr;
    for (const CadFace& f : model.faces)
      if (!f.converged &&
          (!failed || (failed->end == FitEnd::SharedWork && f.end != FitEnd::SharedWork)))
        failed = &f;
    if (failed && failed->surface.points.empty())  // refused before its first fit
      throw DataError(options.source, failed->name,
                      "no fit made: " + fit_end_text(failed->end, ft) + " by its first grid");
    if (failed) {
      const CadFace& f = *failed;
      // Only the position tolerance is an option; say which one failed, and what stopped it.
      const bool position = f.position_deviation > model.tolerance;
      throw DataError(
          options.source, f.name,
          "the fit did not reach the tolerance " + short_number(model.tolerance) + " / " +
              short_number(model.normal_tolerance_deg) + " deg (deviation " +
              short_number(f.position_deviation) + ", " + short_number(f.normal_deviation_deg) +
              " deg; " + fit_end_text(f.end, ft) +
              (f.end == FitEnd::Deadline ? " of " + short_number(options.time_limit_s) + " s"
                                         : std::string()) +
              ")" + (position ? "; try a larger --tolerance" : ""));
    }
    r.size = model.size;
    r.tolerance = model.tolerance;
    r.normal_tolerance_deg = model.normal_tolerance_deg;
    r.sewing_tolerance = kSewingTolerance * model.size;
    sewn = sew_model(model, r.sewing_tolerance, options.source, deadline);
    shell = occt_call({options.source, ""}, "cannot measure the sewn shape",
                      [&] { return analyze_shell(sewn.shape); });
  }
  std::string product = scene.name;
  if (product.empty()) product = std::filesystem::path(options.source).stem().string();
  if (product.empty()) product = target.stem().string();
  write_cad_file(sewn, model, product, *format, target, curves, deadline);

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

}  // namespace

CadExportReport export_cad(const Scene& scene, const std::filesystem::path& target,
                           const CadExportOptions& options) {
  // The boundary: whatever escapes below (OCCT's Standard_Failure, std::exception) becomes a
  // located error naming the scene.
  return occt_call({options.source, ""}, "cannot export",
                   [&] { return export_cad_unguarded(scene, target, options); });
}

std::string cad_report_text(const CadExportReport& r) {
  std::ostringstream os;
  if (r.faces.empty()) {
    os << "wrote " << r.curves << " curve(s) to " << r.target.string() << " ("
       << (r.format == CadFormat::Step ? "STEP AP242" : "IGES")
       << ", millimetres) as exact (rational) B-spline curves\n";
    if (r.broken_curves > 0)
      os << r.broken_curves << " curve(s) broken at a knot of multiplicity degree + 1, written as "
         << r.curve_edges << " edges in all (NAME.1, NAME.2, ...)\n";
    return os.str();
  }
  os << "wrote " << r.faces.size() << " face(s) to " << r.target.string() << " ("
     << (r.format == CadFormat::Step ? "STEP AP242" : "IGES") << ", millimetres): " << r.exact_faces
     << " exact, " << r.fitted_faces << " fitted to " << format_number(r.tolerance) << " and "
     << format_number(r.normal_tolerance_deg) << " deg\n";
  if (r.curves > 0) os << "wrote " << r.curves << " curve(s) as exact (rational) B-spline curves\n";
  if (r.broken_curves > 0)
    os << r.broken_curves << " curve(s) broken at a knot of multiplicity degree + 1, written as "
       << r.curve_edges << " edges in all (NAME.1, NAME.2, ...)\n";
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
