// The `patchlab` Python module: PatchLab's core as NumPy arrays (docs/python.md).
#include "app/python/bindings.hpp"

PYBIND11_MODULE(patchlab, m) {
  m.doc() =
      "PatchLab from Python: load scenes, evaluate their surfaces into NumPy arrays, analyze, "
      "export meshes and STEP/IGES, render images and edit networks with undo (docs/python.md).";
  m.attr("__version__") = PATCHLAB_VERSION;
  pl::python::bind_errors(m);
  pl::python::bind_scene(m);
  pl::python::bind_samples(m);
  pl::python::bind_outputs(m);
  pl::python::bind_document(m);
  pl::python::bind_timing(m);
}
