// The Python module's bridge to the library: keyword arguments as the typed
// options of operations/options.h (the command line's flags, read through
// the same lists), inputs as paths or dicts, and errors as ringid.Error
// carrying the command line's one line.
#ifndef RINGID_PYTHON_CONVERT_H_
#define RINGID_PYTHON_CONVERT_H_

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/pybind11.h>

#include "datasets/dataset.h"
#include "datasets/response_dataset.h"
#include "operations/input_error.h"
#include "operations/option_text.h"
#include "report/report.h"

namespace ringid::python {

namespace py = pybind11;

// Raised as ringid.Error (a ValueError): the line the command line prints
// after "ringid: ", and the file and field it names.
struct Error {
  std::string line;
  std::string file;
  std::string field;
  std::string message;
  static Error Of(const LoadError& e);
  static Error Of(const InputError& e);
  static Error Usage(const std::string& line);  // field: the option the line names
};

// Defines ringid.Error in `m` and translates Error to it.
void RegisterError(py::module_& m);

// A value as the command line would spell option `name`: lists
// comma-joined, dicts NAME=VALUE (or NAME:LO:HI for a pair), floats shortest
// round-trip.
std::string OptionTextOf(const std::string& name, py::handle value);

// TypeError: `name` is none of `options`.
py::type_error UnexpectedKeyword(const std::string& command, const std::string& name,
                                 const std::vector<OptionInfo>& options);

// The settings S of `kwargs`, each keyword one of S's options (TypeError
// otherwise, naming them): every value checked to be of its option's kind in
// the order given, then read through S's list in its order, as the command
// line reads its flags (apps/flags.h, ReadSettings); Error with the same
// line. `argv` gets "ringid.COMMAND" and --NAME=TEXT of each keyword in the
// order given: the provenance's command line.
template <class S>
S ReadOptions(const std::string& command, const py::kwargs& kwargs,
              std::vector<std::string>* argv) {
  const std::vector<OptionInfo> options = OptionsOf<S>();
  std::map<std::string, std::string> texts;
  *argv = {"ringid." + command};
  for (auto [key, value] : kwargs) {
    const std::string name = py::str(key);
    const OptionInfo* info = nullptr;
    for (const OptionInfo& o : options) {
      if (o.name == name) info = &o;
    }
    if (!info) throw UnexpectedKeyword(command, name, options);
    const std::string text = OptionTextOf(name, value);
    if (!OfKind(info->kind, text)) throw Error::Usage(BadValue(name, text, info->kind));
    texts[name] = text;
    argv->push_back("--" + name + "=" + text);
  }
  S settings;
  for (const OptionInfo& o : options) {
    const auto it = texts.find(o.name);
    std::string error;
    if (it != texts.end() && !SetOption(&settings, o.name, it->second, &error)) {
      throw Error::Usage(error);
    }
  }
  return settings;
}
// "name=default: meaning" for each option of S (its list), as a docstring's
// argument list.
std::string OptionsDoc(const std::vector<OptionInfo>& options);

// The provenance of an operation: `argv` (ReadOptions), each input
// (role, path; none for a dict) with its SHA-256, the seed and the
// derivatives.
Provenance RunOf(const std::vector<std::string>& argv,
                 const std::vector<std::pair<std::string, std::string>>& inputs,
                 std::optional<long> seed, Derivatives derivatives = ResidualOptions().derivatives);

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
                                                           const ParameterValues& set);
std::shared_ptr<const LoadedResponses> LoadResponsesFrom(py::handle source);
// A path from str or os.PathLike; none for anything else.
std::optional<std::string> PathOf(py::handle source);
// json.loads(text).
py::object JsonLoads(const std::string& text);

}  // namespace ringid::python

#endif  // RINGID_PYTHON_CONVERT_H_
