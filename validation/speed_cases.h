// The cases the speed figures measure, defined once for the Google Benchmark
// (benchmarks/speed_benchmark.cc) and `ringid bench --suite=speed`
// (validation/speed_suite.cc), so that both time the same problems.
#ifndef RINGID_VALIDATION_SPEED_CASES_H_
#define RINGID_VALIDATION_SPEED_CASES_H_

#include <string>
#include <vector>

#include <Eigen/Core>

#include "datasets/dataset.h"
#include "datasets/response_dataset.h"
#include "estimation/forces.h"
#include "estimation/status.h"
#include "model/parameters.h"

namespace ringid {

// Table 1 (datasets/paper/table1.json under `source_dir`). With
// `in_plane_only`, its in-plane modes alone, the out-of-plane parameters held
// at their initial values (they do not move an in-plane mode) and their ties
// dropped.
Status SpeedTable1(const std::string& source_dir, bool in_plane_only, Dataset* d);

// The paper's Table 2 parameters (datasets/paper/parameters.json).
Status SpeedPaperParameters(const std::string& source_dir, Parameters* p);

// The state matrix of one block, in the matrix type the model uses (on the
// stack, up to 22 x 22).
using SpeedBlock = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 22, 22>;

// The state matrices of the three standing blocks of `p` (x_b, theta_a,
// theta_b; z_b; y_b, gamma_b, psi_b), balanced as the model balances them
// (model/modal.cc): velocities in units of w, the power of two nearest the
// largest sqrt(K_aa / M_aa). The floor a model evaluation is measured
// against: Eigen's EigenSolver on these, with eigenvectors.
std::vector<SpeedBlock> BareEigenBlocks(const Parameters& p);

// Eigen's EigenSolver on each of `blocks`, with eigenvectors or without; a
// value that depends on the result (NaN where a solve failed), so that the
// work cannot be optimised away.
double BareEigenSolve(const std::vector<SpeedBlock>& blocks, bool vectors);

// The next point of a timed run of model evaluations, new every call as in a
// fit: k_bx moves by 1e-15 relative, 128 points in a cycle (`i` counts), so
// the model's standstill cache (64 points) never answers.
void NextSpeedPoint(Parameters* p, int* i);

// The example car tire (ExampleCarTire) measured at `speeds` (m/s, one
// condition each: "v0", "v6", ...), default noise, seed 7; its sidewall and
// contact free (the rolling suite's 14 parameters, its four ties), started
// with dampers 0.8 and the rest 1.25 times the truth.
Status SpeedCarTire(const std::vector<double>& speeds, Dataset* d);

// The forces case of issue 23: the car tire identified (analytic, one start)
// from SpeedCarTire({0, 6, 12}), its covariance of 14 coordinates; and the
// axle's response to known lug forces at 6, 12 and 18 m/s, orders 1-5, all
// five channels, sigma a tenth of each amplitude, 20 lugs per revolution.
Status SpeedForcesCase(ForceParameters* parameters, ResponseDataset* data);

}  // namespace ringid

#endif  // RINGID_VALIDATION_SPEED_CASES_H_
