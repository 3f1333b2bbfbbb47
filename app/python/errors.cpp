// The module's exceptions. patchlab.DataError (a ValueError) carries the message the CLI prints
// after "patchlab: " and its parts: the file (`source`), the place in it (`where`, a JSON path,
// line or token) and what is wrong (`message`). patchlab.EditRefused (a ValueError) is a document
// command refused with the editor's message. The CLI's usage errors (a bad scheme name) are
// ValueErrors; a failed drawing context is a RuntimeError.
#include <exception>

#include "app/cli/arguments.hpp"
#include "app/python/bindings.hpp"
#include "core/base/data_error.hpp"
#include "core/scene/network_edit.hpp"

namespace pl::python {

namespace {

// Module-lifetime exception types, never released: the interpreter may finalise after any
// static destructor of this library would run.
PyObject* g_data_error = nullptr;
PyObject* g_edit_refused = nullptr;

void raise_data_error(const DataError& e) {
  py::object error =
      py::reinterpret_steal<py::object>(PyObject_CallFunction(g_data_error, "s", e.what()));
  if (!error) return;  // the call set its own Python error
  error.attr("source") = e.source();
  error.attr("where") = e.where();
  error.attr("message") = e.message();
  PyErr_SetObject(g_data_error, error.ptr());
}

}  // namespace

void bind_errors(py::module_& m) {
  g_data_error = PyErr_NewExceptionWithDoc(
      "patchlab.DataError",
      "Bad input: the message the CLI prints, with .source (the file), .where (the JSON path, "
      "line or token; may be empty) and .message.",
      PyExc_ValueError, nullptr);
  g_edit_refused = PyErr_NewExceptionWithDoc(
      "patchlab.EditRefused",
      "A document command refused (the scene is unchanged), with the editor's message.",
      PyExc_ValueError, nullptr);
  m.add_object("DataError", py::handle(g_data_error));
  m.add_object("EditRefused", py::handle(g_edit_refused));
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const DataError& e) {
      raise_data_error(e);
    } catch (const EditRefused& e) {
      PyErr_SetString(g_edit_refused, e.what());
    } catch (const UsageError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
}

}  // namespace pl::python
