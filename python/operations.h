// The module's operations (identify, predict, simulate, forces, ...): the
// library's (operations/*.h) on the options of their keyword arguments.
#ifndef RINGID_PYTHON_OPERATIONS_H_
#define RINGID_PYTHON_OPERATIONS_H_

#include <optional>
#include <string>

#include <pybind11/pybind11.h>

#include "datasets/response_dataset.h"
#include "operations/simulate.h"

namespace ringid::python {

// simulate's result: the dataset and truth, or with lug_forces the response
// dataset, the command line would write, and the files it would write them to.
struct SimulateHeld {
  std::optional<Simulated> simulated;
  std::optional<ResponseDataset> response;
  std::string output, truth;
};

void BindSimulate(pybind11::module_& m);
void BindOperations(pybind11::module_& m);

}  // namespace ringid::python

#endif  // RINGID_PYTHON_OPERATIONS_H_
