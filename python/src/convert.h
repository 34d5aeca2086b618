#pragma once
// What every binding file shares (python/src/*.cpp): the core's refusal on its way to Python,
// raised as linkwright.Error by the translator module.cpp registers, and numbers handed to
// Python with None where the core has none, so no NaN or infinity is handed out.

#include "kinematics/io/json.h"
#include "kinematics/io/safe_file.h"
#include "kinematics/model/result.h"
#include "kinematics/model/units.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cmath>
#include <cstdint>
#include <exception>
#include <string>
#include <utility>
#include <vector>

namespace linkwright::python {

namespace py = pybind11;

struct CoreError : std::exception {
  kinematics::Error error;
  explicit CoreError(kinematics::Error e) : error(std::move(e)) {}
  const char* what() const noexcept override { return error.message.c_str(); }
};

template <typename T>
T valueOrThrow(kinematics::Result<T> result) {
  if (!result) throw CoreError(result.error());
  return std::move(result).value();
}

/// An object restored from its pickled tuple `state` by `restore`, which casts the entries: a
/// state of another size or with an entry of another type (another version's, or edited) is
/// refused naming "state", as linkwright.Error, never pybind11's "Unable to cast".
template <typename Restore>
auto fromPickle(const char* cls, const char* layout, const py::tuple& state, std::size_t size, Restore restore) {
  const CoreError refusal(kinematics::Error{
      kinematics::ErrorCode::InvalidValue, "state",
      std::string("linkwright.") + cls + ": not a pickled state of this version (a tuple of " + layout + ")"});
  if (state.size() != size) throw refusal;
  try {
    return restore(state);
  } catch (const py::cast_error&) {
    throw refusal;
  }
}

/// `text` as a Python str, a byte that is not UTF-8 shown as \xNN (a path given as bytes, say):
/// pybind11's own conversion would raise UnicodeDecodeError instead of the refusal.
inline py::str text(const std::string& text) {
  PyObject* decoded = PyUnicode_DecodeUTF8(text.data(), static_cast<Py_ssize_t>(text.size()), "backslashreplace");
  if (decoded == nullptr) throw py::error_already_set();
  return py::reinterpret_steal<py::str>(decoded);
}

inline py::object number(double value) {
  return std::isfinite(value) ? py::object(py::float_(value)) : py::object(py::none());
}

inline py::object degrees(double radians) { return number(kinematics::radToDeg(radians)); }

/// A numpy.ma.MaskedArray of `values`, masked where `defined` is false or a value is not finite
/// (those entries hold 0).
inline py::object maskedArray(const std::vector<double>& values, const std::vector<bool>& defined) {
  py::array_t<double> data(static_cast<py::ssize_t>(values.size()));
  py::array_t<bool> mask(static_cast<py::ssize_t>(values.size()));
  auto d = data.mutable_unchecked<1>();
  auto m = mask.mutable_unchecked<1>();
  for (std::size_t j = 0; j < values.size(); ++j) {
    const bool ok = (defined.empty() || defined[j]) && std::isfinite(values[j]);
    d(static_cast<py::ssize_t>(j)) = ok ? values[j] : 0.0;
    m(static_cast<py::ssize_t>(j)) = !ok;
  }
  return py::module_::import("numpy.ma").attr("MaskedArray")(data, py::arg("mask") = mask);
}

/// A numpy.ma.MaskedArray that takes over `values` and `masked` (true where an entry has no
/// value) without copying them: a column of 10⁷ rows is held once, not twice.
inline py::object maskedArrayTaking(std::vector<double>&& values, std::vector<std::uint8_t>&& masked) {
  const auto n = static_cast<py::ssize_t>(values.size());
  auto* data = new std::vector<double>(std::move(values));
  auto* mask = new std::vector<std::uint8_t>(std::move(masked));
  py::array dataArray(py::dtype::of<double>(), {n}, {static_cast<py::ssize_t>(sizeof(double))}, data->data(),
                      py::capsule(data, [](void* p) { delete static_cast<std::vector<double>*>(p); }));
  py::array maskArray(py::dtype::of<bool>(), {n}, {py::ssize_t{1}}, mask->data(),
                      py::capsule(mask, [](void* p) { delete static_cast<std::vector<std::uint8_t>*>(p); }));
  return py::module_::import("numpy.ma")
      .attr("MaskedArray")(dataArray, py::arg("mask") = maskArray, py::arg("copy") = false);
}

/// The core's JSON (what linkwright-cli --json prints) as Python objects: dicts, lists, str,
/// int, float, bool and None, to the bit (Python's json reads the core's shortest round-trip text).
inline py::object fromJson(const kinematics::io::JsonValue& json) {
  return py::module_::import("json").attr("loads")(json.dump());
}

/// `values` as a 1-D NumPy array of float64.
inline py::array_t<double> array(const std::vector<double>& values) {
  return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
}

/// Writes `contents` to `path` through the core's one writer (kinematics/io/safe_file.h: atomic,
/// the old file kept on failure); a failure raises OSError with the core's sentence and `more`.
inline void writeOrThrow(const std::string& path, std::string_view contents, const std::string& more = {}) {
  if (auto e = kinematics::io::writeFileSafely(path, contents)) {
    PyErr_SetString(PyExc_OSError, (e->message + more).c_str());
    throw py::error_already_set();
  }
}

}  // namespace linkwright::python
