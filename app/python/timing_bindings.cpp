// patchlab._timing: the C++ loops the benchmark script (tests/bench/python_eval_bench.py) compares
// the module with, timed inside this process on the same samples, so both figures of a ratio come
// from one run on one machine state. They are the loops of tests/bench/gb_bench.cpp.
#include <chrono>

#include "app/python/bindings.hpp"
#include "core/patch/patch_types.hpp"

namespace pl::python {

namespace {

template <class F>
std::vector<double> times_ms(int repeats, F&& f) {
  std::vector<double> t;
  for (int r = 0; r < repeats; ++r) {
    const auto a = std::chrono::steady_clock::now();
    f(r);
    const auto b = std::chrono::steady_clock::now();
    t.push_back(std::chrono::duration<double, std::milli>(b - a).count());
  }
  return t;
}

}  // namespace

void bind_timing(py::module_& m) {
  py::module_ t = m.def_submodule(
      "_timing", "C++ timing loops for the benchmark script (not part of the stable API).");
  t.def(
      "evaluate_all_ms",
      [](PySamples& s, int repeats) {
        py::gil_scoped_release release;
        return times_ms(repeats, [&](int) { s.evaluator->evaluate_all(); });
      },
      py::arg("samples"), py::arg("repeats"),
      "Wall times (ms) of PatchEvaluator::evaluate_all on these samples, one per repeat.");
  t.def(
      "move_control_point_ms",
      [](PySamples& s, std::size_t k, int repeats, double step) {
        if (k >= s.evaluator->patch().size()) throw py::index_error("no such control point");
        py::gil_scoped_release release;
        s.evaluator->prepare_influence(k);
        Vec3 p = s.evaluator->patch().control_point(k);
        return times_ms(repeats, [&](int r) {
          p.z += (r % 2 ? -step : step);
          s.evaluator->move_control_point(k, p);
        });
      },
      py::arg("samples"), py::arg("k"), py::arg("repeats"), py::arg("step") = 1e-3,
      "Wall times (ms) of PatchEvaluator::move_control_point(k) moving z by ±step, the "
      "influence column prepared first.");
  t.def(
      "gb_point_index",
      [](const PySamples& s, int i, int j, int k) {
        const auto* gb = patch_as<GBPatch>(s.evaluator->patch());
        if (!gb) throw py::value_error("not a GB patch");
        if (i < 0 || j < 0 || j > gb->degree() || k < 0 || k >= gb->layers())
          throw py::index_error("no such GB control point");
        return gb->index(i, j, k);
      },
      py::arg("samples"), py::arg("i"), py::arg("j"), py::arg("k"),
      "The stored index of GB control point P^i_{j,k}.");
}

}  // namespace pl::python
