// Optimal one-to-one assignment for small problems (modes to labels, measured
// to model modes). Exact, by dynamic programming over subsets of columns.
#ifndef RINGID_MODEL_ASSIGNMENT_H_
#define RINGID_MODEL_ASSIGNMENT_H_

#include <vector>

#include <Eigen/Core>

namespace ringid {

namespace internal {

// Returns, for each row, the column assigned to it so that no column is used
// twice and the sum of scores is largest. Needs rows <= cols <= 16.
std::vector<int> AssignMaxScore(const Eigen::Ref<const Eigen::MatrixXd>& score);

}  // namespace internal

}  // namespace ringid

#endif  // RINGID_MODEL_ASSIGNMENT_H_
