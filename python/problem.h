// ringid.Problem: the weighted residuals that ringid.identify minimises, as
// functions of the coordinates, for fitting them elsewhere (SciPy).
#ifndef RINGID_PYTHON_PROBLEM_H_
#define RINGID_PYTHON_PROBLEM_H_

#include <pybind11/pybind11.h>

namespace ringid::python {

void BindProblem(pybind11::module_& m);

}  // namespace ringid::python

#endif  // RINGID_PYTHON_PROBLEM_H_
