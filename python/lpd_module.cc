// lpd's Python module (_lpd, wrapped by the package in lpd/__init__.py): numpy arrays in,
// numpy arrays and a summary dict out, through the C++ API (lpd/denoise.h). Options are the
// names of `lpd denoise`'s flags; the solve runs without the GIL and stops at the next
// iteration when a signal handler raises (Ctrl-C gives KeyboardInterrupt).
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "lpd/denoise.h"
#include "lpd/parameters.h"

namespace py = pybind11;

namespace {

// An (N, 3) array of reals as points; `what` names the argument in errors.
lpd::PointList PointsFromArray(const py::array& array, const char* what) {
  const char kind = array.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u') {
    throw std::invalid_argument(std::string(what) + " must be an array of numbers, got dtype " +
                                std::string(py::str(array.dtype())));
  }
  if (array.ndim() != 2 || array.shape(1) != 3) {
    std::string shape;
    for (py::ssize_t d = 0; d < array.ndim(); ++d) {
      shape += (d ? ", " : "") + std::to_string(array.shape(d));
    }
    throw std::invalid_argument(std::string(what) + " must have shape (N, 3), got (" + shape +
                                ")");
  }
  const auto values = py::array_t<double, py::array::forcecast>::ensure(array);
  const auto view = values.unchecked<2>();
  lpd::PointList points(static_cast<size_t>(view.shape(0)));
  for (py::ssize_t i = 0; i < view.shape(0); ++i) {
    points[i] = {view(i, 0), view(i, 1), view(i, 2)};
  }
  return points;
}

// Points as an (N, 3) array of `dtype` (the input's float type).
py::array ArrayFromPoints(const lpd::PointList& points, const py::dtype& dtype) {
  py::array_t<double> array({static_cast<py::ssize_t>(points.size()), py::ssize_t{3}});
  auto view = array.mutable_unchecked<2>();
  for (size_t i = 0; i < points.size(); ++i) {
    for (int c = 0; c < 3; ++c) view(i, c) = points[i][c];
  }
  return dtype.is(py::dtype::of<double>()) ? py::array(array) : array.attr("astype")(dtype);
}

template <typename T>
py::array_t<T> ArrayFromVector(const std::vector<T>& values) {
  py::array_t<T> array(static_cast<py::ssize_t>(values.size()));
  if (!values.empty()) std::memcpy(array.mutable_data(), values.data(), values.size() * sizeof(T));
  return array;
}

// A keyword's value as the text the parameter declarations read ("true", "20", "1e-4").
std::string OptionText(const std::string& name, const py::handle& value) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::int_>(value)) return std::to_string(value.cast<long long>());
  if (py::isinstance<py::float_>(value)) return std::string(py::repr(value));
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  throw std::invalid_argument("option " + name + " must be a number, a bool or a string, got " +
                              std::string(py::str(value.get_type().attr("__name__"))));
}

py::dict SummaryDict(const lpd::Summary& s) {
  py::dict d;
  d["version"] = s.version;
  d["termination"] = s.termination;
  d["message"] = s.message;
  d["iterations"] = s.iterations;
  d["passes"] = s.passes;
  d["k"] = s.k;
  d["noise_sigma"] = s.noise_sigma;
  d["read_sigma"] = s.read_sigma;
  d["spacing"] = s.spacing;
  d["eta"] = s.eta;
  d["lambda"] = s.lambda;
  d["mu_l"] = s.mu_l;
  d["mu_m"] = s.mu_m;
  d["input_points"] = s.input_points;
  d["output_points"] = s.output_points;
  d["outliers"] = s.outliers;
  d["isolated"] = s.isolated;
  d["far"] = s.far;
  d["duplicates"] = s.duplicates;
  d["near_repeats"] = s.near_repeats;
  d["separated"] = s.separated;
  d["removed"] = s.removed;
  d["features"] = s.features;
  d["solved_points"] = s.solved_points;
  d["note"] = s.note;
  d["seconds"] = s.seconds;
  d["setup_seconds"] = s.setup_seconds;
  py::dict stages;  // in the order the stages ran (Python dicts keep it)
  for (const auto& [stage, seconds] : s.stage_seconds) stages[py::str(stage)] = seconds;
  d["stage_seconds"] = stages;
  return d;
}

py::dict Denoise(const py::array& points, const py::object& normals, const std::string& preset,
                 const std::string& solver, int threads, const py::kwargs& kwargs) {
  const lpd::PointList input = PointsFromArray(points, "points");
  std::optional<lpd::PointList> input_normals;
  if (!normals.is_none()) {
    input_normals = PointsFromArray(py::array::ensure(normals), "normals");
    if (input_normals->size() != input.size()) {
      throw std::invalid_argument("got " + std::to_string(input_normals->size()) +
                                  " normals for " + std::to_string(input.size()) + " points");
    }
  }
  lpd::Options options(preset);
  options.solver = solver;
  options.num_threads = threads;
  for (const auto& [key, value] : kwargs) {
    const std::string name = py::str(key);
    options.Set(name, OptionText(name, value));
  }

  std::optional<py::error_already_set> signal_error;
  const lpd::ProgressCallback check_signals = [&signal_error](const lpd::Progress&) {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() == 0) return true;
    signal_error.emplace();  // takes the exception a handler raised (KeyboardInterrupt)
    return false;
  };
  lpd::Result result;
  {
    py::gil_scoped_release no_gil;
    result = lpd::Denoise(input, options, input_normals ? &*input_normals : nullptr,
                          check_signals);
  }
  if (signal_error) throw std::move(*signal_error);

  const py::dtype dtype = points.dtype().kind() == 'f' ? points.dtype() : py::dtype::of<double>();
  py::dict out;
  out["points"] = ArrayFromPoints(result.points, dtype);
  out["normals"] = ArrayFromPoints(result.normals, dtype);
  out["index"] = ArrayFromVector(result.source_index);
  out["outlier_score"] = ArrayFromVector(result.outlier_score);
  out["feature_score"] = ArrayFromVector(result.feature_score);
  out["is_outlier"] = ArrayFromVector(result.is_outlier).attr("astype")("bool");
  out["is_feature"] = ArrayFromVector(result.is_feature).attr("astype")("bool");
  out["summary"] = SummaryDict(result.summary);
  return out;
}

// Every parameter's declaration, for help() and for checking names.
py::list Parameters() {
  const lpd::Options defaults;
  py::list list;
  for (const lpd::ParameterInfo& parameter : lpd::DenoiseParameters()) {
    py::dict d;
    d["name"] = parameter.name;
    d["group"] = parameter.group;
    d["help"] = parameter.help;
    d["default"] = defaults.Get(parameter.name);
    d["auto"] = parameter.auto_rule;
    d["paper"] = parameter.paper_value;
    list.append(d);
  }
  return list;
}

}  // namespace

PYBIND11_MODULE(_lpd, module) {
  module.doc() = "lpd's compiled core; use the lpd package";
  module.def("denoise", &Denoise, py::arg("points"), py::arg("normals") = py::none(),
             py::kw_only(), py::arg("preset") = "default", py::arg("solver") = "alternating",
             py::arg("threads") = 0);
  module.def("parameters", &Parameters);
  module.attr("__version__") = lpd::Version();
}
