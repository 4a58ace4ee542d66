// The Python module's bridge to the command line: keyword arguments as the
// flags of apps/flags.cc, inputs as the files the flags name, and errors as
// ringid.Error carrying the command line's one line.
#ifndef RINGID_PYTHON_CONVERT_H_
#define RINGID_PYTHON_CONVERT_H_

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <gflags/gflags.h>
#include <pybind11/pybind11.h>

#include "datasets/dataset.h"
#include "datasets/response_dataset.h"
#include "report/report.h"

namespace ringid::python {

namespace py = pybind11;

// Raised as ringid.Error (a ValueError): the line the command line prints
// after "ringid: ", and a load error's file and field.
struct Error {
  std::string line;
  std::string file;
  std::string field;
  std::string message;
  static Error Of(const LoadError& e);
  static Error Usage(const std::string& line);  // field: the flag the line names
};

// Defines ringid.Error in `m` and translates Error to it.
void RegisterError(py::module_& m);

// While alive: the flags at their defaults, then `kwargs` over them (only
// names of `allowed`); restores every flag when it ends. Hold the GIL for
// all its life: flags are global, and another thread's call sets them too.
class FlagScope {
 public:
  FlagScope(const std::string& command, const std::vector<std::string>& allowed,
            const py::kwargs& kwargs);
  Provenance Run(std::optional<long> seed) const;  // ThisRun of the equivalent command

 private:
  gflags::FlagSaver saver_;
  std::vector<std::string> argv_;
};

// A flag's value as the command line would spell it: lists comma-joined,
// dicts NAME=VALUE (or NAME:LO:HI for a pair), floats shortest round-trip.
std::string FlagText(const std::string& flag, py::handle value);

// "name=default: description" for each flag of `names` (gflags' own table,
// the one --help prints), as a docstring's argument list.
std::string FlagsDoc(const std::vector<std::string>& names);
// `names` without `drop`.
std::vector<std::string> Without(const std::vector<std::string>& names,
                                 const std::vector<std::string>& drop);

// Inputs: a path (str or os.PathLike) or a dict; `source` is the path, ""
// for a dict (messages name it "<dict>").
struct LoadedDataset {
  Dataset dataset;
  std::string source;
  std::string Name() const { return source.empty() ? "<dict>" : source; }
};
struct LoadedParameters {
  Parameters values;
  std::vector<std::string> notes;
  std::string source;
  std::string Name() const { return source.empty() ? "<dict>" : source; }
};
struct LoadedResponses {
  ResponseDataset data;
  std::string source;
  std::string Name() const { return source.empty() ? "<dict>" : source; }
};
std::shared_ptr<const LoadedDataset> LoadDatasetFrom(py::handle source);
std::shared_ptr<const LoadedParameters> LoadParametersFrom(py::handle source,
                                                           const std::map<Param, double>& set);
std::shared_ptr<const LoadedResponses> LoadResponsesFrom(py::handle source);
// A path from str or os.PathLike; none for anything else.
std::optional<std::string> PathOf(py::handle source);
// json.loads(text).
py::object JsonLoads(const std::string& text);

}  // namespace ringid::python

#endif  // RINGID_PYTHON_CONVERT_H_
