#include "python/errors.hpp"

#include <filesystem>
#include <stdexcept>

#include "app/usage_error.hpp"

namespace convray::python {

bool path_exists(const std::string& path) {
  std::error_code error;
  return std::filesystem::exists(path, error);
}

void register_exceptions(py::module_& m) {
  // Lives as long as the module: the translator below raises it.
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  input_error.doc() =
      "Bad input in a mesh file or a scene, with the command line's message "
      "('file:line:col: what is wrong', and for scenes the source line with a caret).";
  py::register_exception_translator([](std::exception_ptr p) {
    if (!p) return;
    try {
      std::rethrow_exception(p);
    } catch (const MissingFile& e) {
      PyErr_SetString(PyExc_FileNotFoundError, e.what());
    } catch (const InputError& e) {
      input_error(e.what());
    } catch (const app::UsageError& e) {  // render options, as the command line words them
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const std::length_error& e) {  // a vector asked to outgrow memory
      PyErr_SetString(PyExc_MemoryError, e.what());
    }
  });
}

}  // namespace convray::python
