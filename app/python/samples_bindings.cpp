// patchlab.PatchSamples: one surface's samples as NumPy arrays that are views of the evaluator's
// own storage (strided over its per-sample records: no copy per sample, no copy at all), and the
// incremental move of a control point (PatchEvaluator::move_control_point: an axpy with the
// point's influence column, then the normals and curvatures of the samples it touches).
#include <cstddef>
#include <numeric>

#include "app/python/bindings.hpp"
#include "core/math/vec.hpp"

namespace pl::python {

namespace {

using Evaluator = std::shared_ptr<PatchEvaluator>;

// A read-only array over `data` that keeps the evaluator (and with it the storage) alive. The
// arrays see later moves of control points: they are the samples, not a snapshot.
template <class T>
py::array view(const Evaluator& ev, const T* data, std::vector<py::ssize_t> shape,
               std::vector<py::ssize_t> strides) {
  py::capsule owner(new Evaluator(ev), [](void* p) { delete static_cast<Evaluator*>(p); });
  static const T empty{};
  py::array a(py::dtype::of<T>(), std::move(shape), std::move(strides), data ? data : &empty,
              owner);
  a.attr("setflags")(py::arg("write") = false);
  return a;
}

// An N x `columns` view of `records`, one row per record: `columns` consecutive values of T, the
// first at `first` in records[0] (nullptr when there are none).
template <class T, class Record>
py::array rows_view(const Evaluator& ev, const std::vector<Record>& records, const T* first,
                    py::ssize_t columns) {
  return view<T>(ev, first, {static_cast<py::ssize_t>(records.size()), columns},
                 {py::ssize_t(sizeof(Record)), py::ssize_t(sizeof(T))});
}

// A Vec3 member of each record of `records`, as an N x 3 view.
template <class Record>
py::array vec3_view(const Evaluator& ev, const std::vector<Record>& records, Vec3 Record::*member) {
  return rows_view(ev, records, records.empty() ? nullptr : &(records[0].*member).x, 3);
}

// A double member of each geometry record, as an N view.
py::array scalar_view(const Evaluator& ev, double SurfaceGeometry::*member) {
  const auto& g = ev->geometry();
  const py::ssize_t n = static_cast<py::ssize_t>(g.size());
  return view<double>(ev, n ? &(g[0].*member) : nullptr, {n},
                      {py::ssize_t(sizeof(SurfaceGeometry))});
}

// A derivative of the jets; the evaluators of a scene keep jets (SampleStorage::Jets).
py::array jet_view(const PySamples& s, Vec3 SurfaceJet::*member) {
  if (s.evaluator->jets().size() != s.evaluator->sample_count())
    throw std::logic_error("the samples keep no derivatives");
  return vec3_view(s.evaluator, s.evaluator->jets(), member);
}

// An array property that is one member of every sample's record, and its docstring.
template <class Member>
struct MemberArray {
  const char* name;
  Member member;
  const char* doc;
};

// The position and derivatives of the jets (jet_view).
const MemberArray<Vec3 SurfaceJet::*> kJetArrays[] = {
    {"positions", &SurfaceJet::p, "N x 3 sample positions."},
    {"su", &SurfaceJet::su, "N x 3 first derivatives in u."},
    {"sv", &SurfaceJet::sv, "N x 3 first derivatives in v."},
    {"suu", &SurfaceJet::suu, "N x 3 second derivatives in u, u."},
    {"suv", &SurfaceJet::suv, "N x 3 mixed second derivatives."},
    {"svv", &SurfaceJet::svv, "N x 3 second derivatives in v, v."},
};

// The curvatures of the geometry records (scalar_view).
const MemberArray<double SurfaceGeometry::*> kCurvatureArrays[] = {
    {"mean_curvature", &SurfaceGeometry::mean,
     "N mean curvatures H (positive where the surface bends towards the normal)."},
    {"gaussian_curvature", &SurfaceGeometry::gaussian, "N Gaussian curvatures K."},
    {"k_min", &SurfaceGeometry::kmin, "N minimum principal curvatures."},
    {"k_max", &SurfaceGeometry::kmax, "N maximum principal curvatures."},
};

py::array changed_samples(PatchEvaluator& ev, std::size_t k) {
  const PatchEvaluator::Support support = ev.influence_support(k);
  if (support.all) {
    py::array_t<uint32_t> all(static_cast<py::ssize_t>(ev.sample_count()));
    std::iota(all.mutable_data(), all.mutable_data() + all.size(), uint32_t(0));
    return all;
  }
  py::array_t<uint32_t> some(static_cast<py::ssize_t>(support.samples.size()));
  std::copy(support.samples.begin(), support.samples.end(), some.mutable_data());
  return some;
}

}  // namespace

void bind_samples(py::module_& m) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double) && sizeof(Vec2) == 2 * sizeof(double));
  py::class_<PySamples> samples(m, "PatchSamples",
                                "The samples of one surface, in the order of its OBJ vertices. The "
                                "arrays are read-only views of PatchLab's own storage: a "
                                "move_control_point shows in them; np.array(x) keeps a copy.");
  samples.def_readonly("name", &PySamples::name, "The face's or patch's name, as in the OBJ file.")
      .def_readonly("face", &PySamples::face, "Its network face index, or -1.")
      .def_readonly("patch", &PySamples::patch, "Its scene patch index, or -1.")
      .def("__len__", [](const PySamples& s) { return s.evaluator->sample_count(); });
  for (const auto& a : kJetArrays)
    samples.def_property_readonly(
        a.name, [member = a.member](const PySamples& s) { return jet_view(s, member); }, a.doc);
  for (const auto& a : kCurvatureArrays)
    samples.def_property_readonly(
        a.name,
        [member = a.member](const PySamples& s) { return scalar_view(s.evaluator, member); },
        a.doc);
  samples
      .def_property_readonly(
          "normals",
          [](const PySamples& s) {
            return vec3_view(s.evaluator, s.evaluator->geometry(), &SurfaceGeometry::normal);
          },
          "N x 3 exact unit normals Su x Sv / |Su x Sv| (limits at singular samples).")
      .def_property_readonly(
          "params",
          [](const PySamples& s) {
            const auto& xs = s.evaluator->tessellation().points;
            return rows_view(s.evaluator, xs, xs.empty() ? nullptr : &xs[0].x, 2);
          },
          "N x 2 domain points (u, v) of the samples.")
      .def_property_readonly(
          "triangles",
          [](const PySamples& s) {
            const auto& t = s.evaluator->tessellation().triangles;
            return rows_view(s.evaluator, t, t.empty() ? nullptr : t[0].data(), 3);
          },
          "T x 3 sample indices of the triangles, oriented like the normals.")
      .def_property_readonly(
          "control_points",
          [](const PySamples& s) {
            const Patch& p = s.evaluator->patch();
            py::array_t<double> out({py::ssize_t(p.size()), py::ssize_t(3)});
            for (std::size_t k = 0; k < p.size(); ++k)
              for (int c = 0; c < 3; ++c) out.mutable_at(k, c) = p.control_point(k)[c];
            return out;
          },
          "K x 3 copy of the control points of the surface's patch (for a network face: its "
          "Gregory or GB patch, derived from the network).")
      .def("evaluate_at", &evaluate_points, py::arg("uv"), py::arg("out") = py::none(),
           "The patch of these samples (moved points included) at the N x 2 domain points uv: "
           "a dict of arrays positions, su, sv, suu, suv, svv, normals (N x 3), mean_curvature, "
           "gaussian_curvature, k_min, k_max and singular (N). Where Su x Sv vanishes "
           "(singular), normal and curvatures are 0. ValueError for a point outside the domain. "
           "out: a dict an earlier call returned for as many points, filled again and returned "
           "(no new arrays).")
      .def(
          "move_control_point",
          [](PySamples& s, std::size_t k, const py::handle& p) {
            if (k >= s.evaluator->patch().size())
              throw py::index_error("control point " + std::to_string(k) + " of " +
                                    std::to_string(s.evaluator->patch().size()));
            const Vec3 to = to_point(p, "move_control_point");
            {
              py::gil_scoped_release release;
              s.evaluator->move_control_point(k, to);
            }
            return changed_samples(*s.evaluator, k);
          },
          py::arg("k"), py::arg("position"),
          "Moves control point k of these samples' own copy of the patch (not the scene: edit "
          "scenes through Document) and updates only the samples it influences. Returns their "
          "indices (uint32); the arrays show the new values.");
}

}  // namespace pl::python
