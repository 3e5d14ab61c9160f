#pragma once
// C++ errors as Python exceptions, with the text the command line prints for them:
//
//   convray.InputError (a ValueError)  bad input in a file or scene: "file:line:col: ..."
//   FileNotFoundError                  a mesh or scene file that does not exist (same text)
//   ValueError                         bad arguments: shapes, NaN, radii, render options
//   MemoryError                        out of memory (pybind11's own translation)
//
// Nothing reaches std::terminate: every exception the libraries throw is translated.
#include <pybind11/pybind11.h>

#include <string>
#include <utility>

#include "util/error.hpp"

namespace convray::python {

namespace py = pybind11;

// An InputError about a file that is not there: FileNotFoundError in Python.
class MissingFile : public InputError {
 public:
  explicit MissingFile(const InputError& e) : InputError(e) {}
};

// Registers convray.InputError and the translators above on `m`.
void register_exceptions(py::module_& m);

bool path_exists(const std::string& path);

// Runs `read(path)`; an InputError for a path that does not exist becomes a MissingFile.
template <class Read>
auto reading(const std::string& path, Read&& read) {
  try {
    return std::forward<Read>(read)();
  } catch (const MissingFile&) {
    throw;
  } catch (const InputError& e) {
    if (!path_exists(path)) throw MissingFile(e);
    throw;
  }
}

}  // namespace convray::python
