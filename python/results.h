// The module's result types: a report of the command line (report/report.h)
// held whole, with attribute access to its fields, to_dict() equal to the
// JSON the command line writes, and NumPy arrays where the result has them.
#ifndef RINGID_PYTHON_RESULTS_H_
#define RINGID_PYTHON_RESULTS_H_

#include <string>

#include <pybind11/pybind11.h>

#include "python/convert.h"
#include "report/report.h"

namespace ringid::python {

template <class R>
struct Held {
  R report;
};

template <class Result>
const Result& ResultOf(const DatasetBody<Result>& body) {
  return body.result;
}
inline const PredictBody& ResultOf(const PredictBody& body) { return body; }

// The class `name` for reports of type R: to_dict, to_json, text, the
// report's fields as attributes.
template <class R>
py::class_<Held<R>, std::shared_ptr<Held<R>>> BindResult(py::module_& m, const char* name,
                                                         const char* doc) {
  using H = Held<R>;
  py::class_<H, std::shared_ptr<H>> c(m, name, doc);
  c.def("to_json", [](const H& h) { return ReportText(h.report); },
        "The report as the JSON text `ringid` writes with --output.");
  c.def("to_dict", [](const H& h) { return JsonLoads(ReportText(h.report)); },
        "The report as a dict: json.loads of to_json(), the command line's report.");
  c.def_property_readonly("text", [](const H& h) { return ResultOf(h.report.body).FullReport(); },
                          "The text the command line prints.");
  c.def("__getattr__", [name](const H& h, const std::string& field) -> py::object {
    py::dict d = JsonLoads(ReportText(h.report));
    if (!d.contains(field)) {
      throw py::attribute_error(std::string("'") + name + "' object has no attribute '" + field + "'");
    }
    return d[field.c_str()];
  });
  c.def("__dir__", [](py::object self) {
    py::list names = py::module_::import("builtins").attr("object").attr("__dir__")(self);
    for (auto item : self.attr("to_dict")().cast<py::dict>()) names.append(item.first);
    return names;
  });
  c.def("__repr__", [name](const H& h) {
    return std::string("<ringid.") + name + " " + ToString(ResultOf(h.report.body).status.outcome) +
           ">";
  });
  return c;
}

}  // namespace ringid::python

#endif  // RINGID_PYTHON_RESULTS_H_
