// The library's typed errors as Python exceptions (stockbridge.Error and its kinds).
#include "binding_support.hpp"

#include <complex>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <pybind11/complex.h>
#include <pybind11/stl.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/core/typical_ranges.hpp"

namespace stockbridge::python {

void expose_errors(py::module_& m) {
  static py::exception<Error> error(m, "Error", PyExc_RuntimeError);
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<InvalidParameter> invalid_parameter(m, "InvalidParameter", PyExc_ValueError);
  static py::exception<UnusualValueError> unusual_value_error(m, "UnusualValueError", input_error.ptr());
  static py::exception<NumericalError> numerical_error(m, "NumericalError", error.ptr());
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const UnusualValueError& e) {
      unusual_value_error((std::string(e.what()) + " (allow_unusual=True takes it as given)").c_str());
    } catch (const InputError& e) {
      input_error(e.what());
    } catch (const InvalidParameter& e) {
      invalid_parameter(e.what());
    } catch (const NumericalError& e) {
      numerical_error(e.what());
    } catch (const Error& e) {
      error(e.what());
    }
  });
}

}  // namespace stockbridge::python
