// The pieces of the `patchlab` Python module (module.cpp binds them in this order): the
// exceptions, scenes and their samples, outputs (analysis, meshes, CAD, images), the document
// with its undoable commands, and the timing loops of the benchmark script.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>

#include "core/domain/tessellation_cache.hpp"
#include "core/eval/patch_evaluator.hpp"
#include "core/scene/scene.hpp"

namespace pl::python {

namespace py = pybind11;

// A scene and the file it came from: every message about it names that file, as the CLI's do.
// The tessellations of the densities it was evaluated at are kept for its next evaluations
// (shared by its copies: they have the same domains), and so is the sample storage of results
// Python has dropped: evaluating again writes into it instead of mapping and zeroing new memory
// (core/eval/sample_buffer_pool.hpp), as PatchEvaluator::evaluate_all writes into its own.
struct PyScene {
  PyScene(Scene s, std::string from) : scene(std::move(s)), source(std::move(from)) {}
  Scene scene;
  std::string source;
  std::shared_ptr<TessellationCache> tessellations = std::make_shared<TessellationCache>();
  std::shared_ptr<SampleBufferPool> sample_buffers = std::make_shared<SampleBufferPool>();
};

// The samples of one surface of an evaluated scene. Its arrays are views of the evaluator's
// storage (no copy), kept alive by the arrays themselves.
struct PySamples {
  std::string name;
  int face = -1, patch = -1;  // network face or scene patch index (-1: not that kind)
  std::shared_ptr<PatchEvaluator> evaluator;
};

// PatchSamples.evaluate_at (point_evaluation.cpp).
py::dict evaluate_points(const PySamples& samples,
                         const py::array_t<double, py::array::c_style | py::array::forcecast>& uv,
                         const std::optional<py::dict>& out);

void bind_errors(py::module_& m);
void bind_scene(py::module_& m);
void bind_samples(py::module_& m);
void bind_outputs(py::module_& m);
void bind_document(py::module_& m);
void bind_timing(py::module_& m);

// A point from Python: any sequence of three finite numbers within the coordinate bound of the
// scene format (core/io/input_limits.hpp); ValueError otherwise.
Vec3 to_point(const py::handle& p, const char* what);
// "gregory", "gb" or None (the scene's own schemes), as the CLI's --scheme; ValueError otherwise.
std::optional<FaceScheme> to_scheme(const std::optional<std::string>& scheme);
// The density bound of the CLI (1 ... kMaxDensity); ValueError otherwise.
int checked_density(int density);

}  // namespace pl::python
