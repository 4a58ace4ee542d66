#include "python/convert.h"

#include <pybind11/eval.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "datasets/parameter_files.h"
#include "datasets/tir_parameters.h"

namespace ringid::python {

Error Error::Of(const LoadError& e) { return Of(InputError::Of(e)); }

Error Error::Of(const InputError& e) { return {e.line, e.file, e.field, e.message}; }

Error Error::Usage(const std::string& line) { return Of(InputError::Option(line)); }

void RegisterError(py::module_& m) {
  py::exec(R"(
class Error(ValueError):
    """A bad input or option: str(e) is the line `ringid` prints after "ringid: ".

    file: the file read ("" for options), field: the JSON path or key in it,
    or the option's name ("" where none), message: what is wrong with it.
    """

    def __init__(self, line, file="", field="", message=None):
        super().__init__(line)
        self.file = file
        self.field = field
        self.message = line if message is None else message
)",
           m.attr("__dict__"));
  static py::handle error_type = py::object(m.attr("Error")).release();
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const Error& e) {
      py::object value = error_type(e.line, e.file, e.field, e.message);
      PyErr_SetObject(error_type.ptr(), value.ptr());
    }
  });
}

namespace {

std::string Join(py::handle items, const std::string& name) {
  std::string out;
  for (py::handle item : items) out += (out.empty() ? "" : ",") + OptionTextOf(name, item);
  return out;
}

}  // namespace

std::string OptionTextOf(const std::string& name, py::handle value) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::int_>(value)) return py::str(value);
  if (py::isinstance<py::float_>(value)) return py::repr(value);
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (const auto path = PathOf(value)) return *path;
  if (py::isinstance<py::dict>(value)) {  // set={"c_b": 1}, bounds={"k_b": (1, 2)}
    std::string out;
    for (auto [k, v] : value.cast<py::dict>()) {
      out += (out.empty() ? "" : ",") + py::str(k).cast<std::string>();
      if (py::isinstance<py::tuple>(v) || py::isinstance<py::list>(v)) {
        for (py::handle bound : v) out += ":" + OptionTextOf(name, bound);
      } else {
        out += "=" + OptionTextOf(name, v);
      }
    }
    return out;
  }
  if (py::isinstance<py::sequence>(value)) return Join(value, name);
  try {  // numpy scalars and the like
    return py::repr(py::float_(py::reinterpret_borrow<py::object>(value)));
  } catch (const py::error_already_set&) {
    throw Error::Usage("--" + name + ": cannot read a " +
                       py::str(py::type::of(value).attr("__name__")).cast<std::string>());
  }
}

py::type_error UnexpectedKeyword(const std::string& command, const std::string& name,
                                 const std::vector<OptionInfo>& options) {
  std::string list;
  for (const OptionInfo& o : options) list += (list.empty() ? "" : ", ") + o.name;
  return py::type_error("ringid." + command + "() got an unexpected keyword argument '" + name +
                        "' (it takes " + list + ")");
}

std::string OptionsDoc(const std::vector<OptionInfo>& options) {
  std::string doc;
  for (const OptionInfo& o : options) {
    const std::string value = o.kind == OptionKind::kText ? "'" + o.default_text + "'"
                              : o.kind == OptionKind::kBool
                                  ? (o.default_text == "true" ? "True" : "False")
                                  : o.default_text;
    doc += "    " + o.name + "=" + value + ": " + o.help + "\n";
  }
  return doc;
}

Provenance RunOf(const std::vector<std::string>& argv,
                 const std::vector<std::pair<std::string, std::string>>& inputs,
                 std::optional<long> seed, Derivatives derivatives) {
  std::vector<const char*> args;
  for (const std::string& a : argv) args.push_back(a.c_str());
  Provenance p = MakeProvenance(static_cast<int>(args.size()), args.data(), inputs, seed);
  p.derivatives = derivatives;
  return p;
}

std::optional<std::string> PathOf(py::handle source) {
  if (py::isinstance<py::str>(source)) return source.cast<std::string>();
  if (py::hasattr(source, "__fspath__")) {
    return py::module_::import("os").attr("fsdecode")(source).cast<std::string>();
  }
  return std::nullopt;
}

py::object JsonLoads(const std::string& text) {
  return py::module_::import("json").attr("loads")(text);
}

namespace {

// A dict as JSON text; Error naming the input when it is not JSON.
std::string DictText(py::handle source, const char* what) {
  if (!py::isinstance<py::dict>(source)) {
    throw Error::Usage(std::string(what) + ": a path (str, os.PathLike) or a dict, not " +
                       py::str(py::type::of(source).attr("__name__")).cast<std::string>());
  }
  try {
    return py::module_::import("json").attr("dumps")(source, py::arg("allow_nan") = false)
        .cast<std::string>();
  } catch (const py::error_already_set& e) {
    throw Error{std::string("<dict>: ") + e.what(), "<dict>", "", e.what()};
  }
}

}  // namespace

std::shared_ptr<const LoadedDataset> LoadDatasetFrom(py::handle source) {
  auto in = std::make_shared<LoadedDataset>();
  LoadError error;
  bool ok;
  if (const auto path = PathOf(source)) {
    in->source = *path;
    ok = LoadDataset(*path, &in->dataset, &error);
  } else {
    const std::string text = DictText(source, "dataset");
    ok = ParseDataset(text, "<dict>", &in->dataset, &error);
  }
  if (!ok) throw Error::Of(error);
  return in;
}

std::shared_ptr<const LoadedResponses> LoadResponsesFrom(py::handle source) {
  auto in = std::make_shared<LoadedResponses>();
  LoadError error;
  bool ok;
  if (const auto path = PathOf(source)) {
    in->source = *path;
    ok = LoadResponseDataset(*path, &in->data, &error);
  } else {
    ok = ParseResponseDataset(DictText(source, "dataset"), "<dict>", &in->data, &error);
  }
  if (!ok) throw Error::Of(error);
  return in;
}

std::shared_ptr<const LoadedParameters> LoadParametersFrom(py::handle source,
                                                           const ParameterValues& set) {
  auto in = std::make_shared<LoadedParameters>();
  LoadError error;
  if (const auto path = PathOf(source)) {
    in->source = *path;
    if (!LoadParameters(*path, set, &in->values, &error, &in->notes)) throw Error::Of(error);
    return in;
  }
  // The reader of parameter files reads files: the dict goes through one.
  const std::string text = DictText(source, "parameters");
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() /
      ("ringid-parameters-" + std::to_string(reinterpret_cast<std::uintptr_t>(in.get())) + ".json");
  std::ofstream(file) << text;
  const bool ok = LoadParameters(file.string(), set, &in->values, &error, &in->notes);
  std::filesystem::remove(file);
  if (!ok) {
    error.file = "<dict>";
    throw Error::Of(error);
  }
  return in;
}

}  // namespace ringid::python
