#include "core/cad/cad_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/analysis/scene_analysis.hpp"  // angle_deg
#include "core/base/parallel_for.hpp"
#include "core/cad/side_matching.hpp"
#include "core/io/json_node.hpp"  // short_number

namespace pl {

namespace {

// Parameter of side s at t (sides as in fit_surface).
Vec2 side_uv(int s, double t) {
  switch (s) {
    case 0:
      return {t, 0};
    case 1:
      return {1, t};
    case 2:
      return {t, 1};
    default:
      return {0, t};
  }
}

// The curve of side s of a piece's function: position and derivative along the side.
CurveFunction side_function(const SurfaceFunction& f, int s) {
  return [f, s](std::span<const double> t, std::span<CurvePoint> out) {
    std::vector<Vec2> uv(t.size());
    for (std::size_t k = 0; k < t.size(); ++k) uv[k] = side_uv(s, t[k]);
    std::vector<SurfacePoint> sp(t.size());
    f(uv, sp);
    for (std::size_t k = 0; k < t.size(); ++k)
      out[k] = {sp[k].p, s % 2 == 0 ? sp[k].su : sp[k].sv, Vec3(0)};
  };
}

// Runs body(i) for i in [0, n), one face per task (each takes milliseconds), on the core's
// work-stealing scheduler; rethrows the first exception.
template <class Body>
void parallel_for(int n, Body&& body) {
  parallel_chunks(std::size_t(std::max(n, 0)), 1, [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) body(int(i));
  });
}

double exact_normal_deviation(const CadSurface& s, const SurfaceFunction& f, int k,
                              double& position) {
  std::vector<Vec2> uv;
  for (int a = 0; a <= k; ++a)
    for (int b = 0; b <= k; ++b) uv.emplace_back(double(a) / k, double(b) / k);
  std::vector<SurfacePoint> truth(uv.size());
  f(uv, truth);
  double dn = 0;
  position = 0;
  for (std::size_t i = 0; i < uv.size(); ++i) {
    const CadSurface::Jet1 e = s.evaluate(uv[i].x, uv[i].y);
    position = std::max(position, glm::length(e.p - truth[i].p));
    const Vec3 nt = glm::cross(truth[i].su, truth[i].sv);
    if (glm::length(nt) > 1e-14 * glm::length(truth[i].su) * glm::length(truth[i].sv))
      dn = std::max(dn, angle_deg(glm::cross(e.su, e.sv), nt));
  }
  return dn;
}

}  // namespace

std::string fit_end_text(FitEnd end, const FitTolerance& tol) {
  switch (end) {
    case FitEnd::Converged:
      return "converged";
    case FitEnd::Spans:
      return "no span left to split within " + std::to_string(tol.max_spans) + " per direction";
    case FitEnd::Curve:
      return "a side curve's own deviation bends the surface past the tolerance";
    case FitEnd::Work:
      return "its work bound of " + short_number(double(tol.max_work)) + " grid points reached";
    case FitEnd::SharedWork:
      return "the export's work bound of " + short_number(double(tol.max_shared_work)) +
             " grid points reached (all fits together)";
    case FitEnd::Deadline:
      return "stopped at the time limit";
  }
  return {};
}

double default_tolerance(double diagonal) {
  return std::min(1e-3, 1e-5 * diagonal);
}

double pieces_size(const std::vector<CadPiece>& pieces) {
  Vec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  std::vector<Vec2> uv;
  for (int a = 0; a <= 8; ++a)
    for (int b = 0; b <= 8; ++b) uv.emplace_back(a / 8.0, b / 8.0);
  std::vector<SurfacePoint> sp(uv.size());
  for (const CadPiece& p : pieces) {
    piece_function(p)(uv, sp);
    for (const SurfacePoint& s : sp) lo = glm::min(lo, s.p), hi = glm::max(hi, s.p);
  }
  return pieces.empty() ? 0.0 : glm::length(hi - lo);
}

CadModel build_cad_model(std::vector<CadPiece> pieces, const CadModelOptions& options) {
  CadModel m;
  m.size = pieces_size(pieces);
  m.tolerance = options.tolerance ? *options.tolerance : default_tolerance(m.size);
  if (!(m.tolerance > 0) || !std::isfinite(m.tolerance))
    throw std::invalid_argument("the tolerance must be positive");
  m.normal_tolerance_deg = options.normal_tolerance_deg;
  const int n = static_cast<int>(pieces.size());
  std::vector<SurfaceFunction> fn(n);
  for (int i = 0; i < n; ++i) fn[i] = piece_function(pieces[i]);

  // Sides of every piece, sampled; exact pieces take part only as providers of exact curves.
  std::vector<SideSamples> samples(4 * std::size_t(n));
  std::vector<SideRef> refs(4 * std::size_t(n));
  parallel_for(n, [&](int i) {
    for (int s = 0; s < 4; ++s) {
      std::vector<CurvePoint> c(kSideParams.size());
      side_function(fn[i], s)(kSideParams, c);
      for (std::size_t k = 0; k < c.size(); ++k) samples[4 * i + s][k] = c[k].p;
      refs[4 * i + s] = {i, s};
    }
  });
  const std::vector<SideGroup> groups = match_sides(samples, refs, 1e-9 * m.size);

  // One curve per group that has a fitted member: exact if any member knows it, else fitted.
  std::vector<std::array<CadCurve, 4>> sides(n);
  std::vector<int> fitted_groups;
  std::vector<std::array<int, 4>> fitted_group_of(n, {-1, -1, -1, -1});  // index in fitted_groups
  for (int g = 0; g < static_cast<int>(groups.size()); ++g) {
    const SideGroup& G = groups[g];
    bool any_fitted = false;
    std::optional<CadCurve> exact;  // in the direction of members[0]
    for (std::size_t k = 0; k < G.members.size(); ++k) {
      const CadPiece& p = pieces[G.members[k].piece];
      const int s = G.members[k].side;
      std::optional<CadCurve> c;
      if (p.exact && !p.exact->rational())
        c = p.exact->boundary(s);
      else if (!p.exact)
        c = p.known_sides[s], any_fitted = true;
      // The simplest exact form among them (they are the same curve).
      if (c && (!exact || c->degree < exact->degree ||
                (c->degree == exact->degree && c->points.size() < exact->points.size())))
        exact = G.reversed[k] ? c->reversed() : *c;
    }
    if (!any_fitted) continue;
    if (exact) {
      if (G.members.size() > 1) ++m.shared_exact_sides;
      for (std::size_t k = 0; k < G.members.size(); ++k)
        sides[G.members[k].piece][G.members[k].side] = G.reversed[k] ? exact->reversed() : *exact;
    } else {
      for (const SideRef& r : G.members)
        fitted_group_of[r.piece][r.side] = static_cast<int>(fitted_groups.size());
      fitted_groups.push_back(g);
    }
  }
  m.shared_fitted_curves =
      static_cast<int>(std::count_if(fitted_groups.begin(), fitted_groups.end(),
                                     [&](int g) { return groups[g].members.size() > 1; }));

  // Fitted curves start at a quarter of the tolerance. A surface pinned to a curve inherits its
  // error divided by the surface's first span across it (its cross derivative must bend to meet
  // the curve), so where a surface fails, its fitted curves are tightened tenfold and the
  // surfaces on them fitted again (up to three times).
  const int nf = static_cast<int>(fitted_groups.size());
  std::vector<double> curve_position(nf, m.tolerance / 4);
  std::vector<char> curve_due(nf, 1), face_due(n, 1);
  std::vector<std::size_t> face_work(n, 0);
  FitTolerance tol;
  tol.position = m.tolerance;
  tol.normal_deg = options.normal_tolerance_deg;
  tol.max_spans = options.max_spans;
  tol.max_work = options.max_work;
  tol.deadline = options.deadline;
  std::atomic<std::size_t> total_work{0};
  tol.shared_work = &total_work;
  tol.max_shared_work = options.max_total_work;
  m.faces.resize(n);
  for (int round = 0;; ++round) {
    std::vector<std::string> failures(nf);
    parallel_for(nf, [&](int k) {
      if (!curve_due[k]) return;
      const SideGroup& G = groups[fitted_groups[k]];
      int degree = 3;
      for (const SideRef& r : G.members)
        if (!pieces[r.piece].exact) degree = std::max(degree, pieces[r.piece].degree);
      FitTolerance ct;
      ct.position = curve_position[k];
      ct.normal_deg = options.normal_tolerance_deg / 5;
      ct.max_spans = 4 * options.max_spans;  // curves are cheap; singular ends need grading
      ct.max_work = options.max_work;
      ct.deadline = options.deadline;
      ct.shared_work = &total_work;
      ct.max_shared_work = options.max_total_work;
      const SideRef ref = G.members.front();
      const CurveFit fit = fit_curve(side_function(fn[ref.piece], ref.side), degree, ct);
      if (!fit.converged)
        failures[k] = pieces[ref.piece].name + ": a side curve did not reach the tolerance " +
                      short_number(ct.position) + " / " + short_number(ct.normal_deg) +
                      " deg (deviation " + short_number(fit.position_deviation) + ", " +
                      short_number(fit.tangent_deviation_deg) + " deg with " +
                      std::to_string(fit.curve.points.size()) + " points; " +
                      fit_end_text(fit.end, ct) + ")";
      for (std::size_t i = 0; i < G.members.size(); ++i)
        sides[G.members[i].piece][G.members[i].side] =
            G.reversed[i] ? fit.curve.reversed() : fit.curve;
    });
    for (const std::string& f : failures)
      if (!f.empty()) throw std::runtime_error(f);

    parallel_for(n, [&](int i) {
      if (!face_due[i]) return;
      CadFace& f = m.faces[i];
      f.name = pieces[i].name;
      f.owner = pieces[i].owner;
      if (pieces[i].exact) {
        f.exact = true;
        f.surface = *pieces[i].exact;
        validate_cad_surface(f.surface);
        f.check_points = 33;
        f.normal_deviation_deg = exact_normal_deviation(f.surface, fn[i], 32, f.position_deviation);
        return;
      }
      // The face's work bound covers all its fits (a face is fitted again when a curve it
      // shares is tightened): what is left of it bounds this one.
      if (face_work[i] >= options.max_work) {
        f.converged = false, f.end = FitEnd::Work;
        return;
      }
      FitTolerance face_tol = tol;
      face_tol.max_work = options.max_work - face_work[i];
      const SurfaceFit fit = fit_surface(fn[i], sides[i], face_tol);
      face_work[i] += fit.work;
      // A face stopped by its own bound or the deadline is refused, and with it the export: the
      // shared bound is spent so that the fits still running stop at their next refinement.
      if (!fit.converged && (fit.end == FitEnd::Work || fit.end == FitEnd::Deadline))
        total_work.store(options.max_total_work + 1);
      f.surface = fit.surface;
      f.position_deviation = fit.position_deviation;
      f.normal_deviation_deg = fit.normal_deviation_deg;
      f.check_points = fit.check_points;
      f.converged = fit.converged;
      f.end = fit.end;
      f.work = face_work[i];
    });
    if (round == 3) break;
    // A face stopped by its work bound or the deadline is refused: no tightening round for it.
    if (std::any_of(m.faces.begin(), m.faces.end(), [](const CadFace& f) {
          return !f.converged && (f.end == FitEnd::Work || f.end == FitEnd::SharedWork ||
                                  f.end == FitEnd::Deadline);
        }))
      break;
    std::fill(curve_due.begin(), curve_due.end(), 0);
    std::fill(face_due.begin(), face_due.end(), 0);
    bool again = false;
    for (int i = 0; i < n; ++i) {
      if (m.faces[i].converged) continue;
      for (int s = 0; s < 4; ++s) {
        const int k = fitted_group_of[i][s];
        if (k < 0 || curve_due[k]) continue;
        curve_due[k] = 1, again = true;
        curve_position[k] /= 10;
        for (const SideRef& r : groups[fitted_groups[k]].members) face_due[r.piece] = 1;
      }
    }
    if (!again) break;
  }
  for (const CadFace& f : m.faces) (f.exact ? m.exact_faces : m.fitted_faces)++;
  m.pieces = std::move(pieces);
  return m;
}

}  // namespace pl
