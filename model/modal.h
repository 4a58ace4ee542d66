// The state-space modal solution of eqs. (13) and (17), with robust labels.
#ifndef RINGID_MODEL_MODAL_H_
#define RINGID_MODEL_MODAL_H_

#include <array>
#include <complex>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "model/names.h"
#include "model/parameters.h"
#include "model/system.h"

namespace ringid {

using ShapeVector = Eigen::Matrix<std::complex<double>, kNumDofs, 1>;
using RealShapeVector = Eigen::Matrix<double, kNumDofs, 1>;

// First derivatives of one mode with respect to every catalogue parameter
// (columns; zero where the block's state matrix does not depend on it):
// d lambda = y dA v with y the left eigenvector (y v = 1), and the shape's by
// expansion over every other eigenvector of the block's state matrix,
// d v = sum_k y_k dA v / (lambda - lambda_k) v_k, normalised as Mode::shape
// (docs/model.md §15).
struct ModeDerivatives {
  Eigen::Matrix<std::complex<double>, 1, kNumParams> eigenvalue;
  Eigen::Matrix<std::complex<double>, kNumDofs, kNumParams> shape;

  double Frequency(int p) const;  // d frequency_hz / d p
  double DampingRatio(const std::complex<double>& lambda, int p) const;
};

struct Mode {
  ModeLabel label;
  // The eigenvalue lambda of A = [[0, I], [-M^-1 K, -M^-1 C]] with Im > 0.
  std::complex<double> eigenvalue;
  double frequency_hz;   // damped: Im(lambda) / 2 pi (docs/conventions.md §2)
  double damping_ratio;  // -Re(lambda) / |lambda|
  // Displacement eigenvector, rotated so its largest-magnitude component is
  // real and positive, scaled so that component is 1; zero off its block.
  ShapeVector shape;
  // Share of the mode's generalised strain energy |w^T K_label v| carried by
  // the elements of each label (w the left eigenvector); sums to <= 1.
  std::array<double, kNumLabels> energy;
  // Set by SolveModes when asked for derivatives and they exist.
  std::shared_ptr<const ModeDerivatives> derivatives;

  Plane plane() const { return LabelPlane(label); }
  // The convention of docs/conventions.md §2 for comparison with a measured real shape.
  RealShapeVector RealShape() const { return shape.real(); }
  // The paper's Tables 4-5 convention (docs/model.md section 8): real part of
  // the displacement half of the state vector [v; lambda v] scaled to unit
  // 2-norm, largest entry real.
  RealShapeVector PaperShape() const;
};

struct ModalSolution {
  bool ok = false;
  std::string error;            // why, when !ok
  std::vector<Mode> modes;      // ascending frequency
  std::vector<ModeLabel> vanished;  // labels whose pair of roots is real
  // Roots without oscillation (1/s), ascending: rolling, the contact slip
  // lags and any overdamped pair; never paired with a measured mode.
  std::vector<double> real_roots;
  // Why a mode has no derivatives although they were asked for: two
  // eigenvalues of one block coincide, where the eigenvectors have none.
  std::string derivatives_undefined;

  const Mode* Find(ModeLabel label) const;
};

// The unit of the balanced velocity states (docs/model.md §8): the power of
// two nearest sqrt(largest_k_over_m), the largest K_aa / M_aa of a block; 1
// where that is not positive and finite.
double BalancingFrequency(double largest_k_over_m);

// Solves each block of coupled active degrees of freedom, and labels its modes
// by the one-to-one assignment that maximises the product of energy shares.
// At speed, the slip states of system.lags() join the state vector
// (docs/rolling.md) and the labels are by energy as at standstill.
// With `jets` (the same system assembled with ParameterJet scalars) each
// mode also carries its derivatives.
ModalSolution SolveModes(const MechanicalSystem& system,
                         const BasicSystem<ParameterJet>* jets = nullptr);

// Labels by continuation (model/continuation.cc).

// The modes at `speed` of the systems assemble(v), labelled by continuation
// from standstill: each step in speed pairs modes by shape (MAC) and keeps
// each eigenvalue nearer its prediction (linear in speed from the two steps
// before) than to the predictions of its neighbours, quartering the step
// until it does (docs/rolling.md §5).
// `standing` is SolveModes(assemble(0)). With `assemble_jets` the modes at
// `speed` carry their derivatives. `forced`, if given, says whether a step of
// the finest size took the assignment by shape as it is.
ModalSolution SolveRolling(
    const std::function<MechanicalSystem(double)>& assemble, double speed,
    ModalSolution standing,
    const std::function<BasicSystem<ParameterJet>(double)>& assemble_jets = nullptr,
    bool* forced = nullptr);

// The modes of `system` labelled as those of `near`, the solution of a nearby
// system at the same speed, where Follow's rule for nearby points joins them
// (MAC >= 0.9 one to one, as many modes; docs/rolling.md §5); nullopt where
// it does not.
std::optional<ModalSolution> SolveNear(const ModalSolution& near, const MechanicalSystem& system,
                                       const BasicSystem<ParameterJet>* jets = nullptr);

// Whether `at`'s labels are those the same rule carries from `near`, the
// modes of a nearby system at the same speed (at standstill, where labels are
// by energy, two nearby points can label a pair of modes differently).
bool SameLabelsNear(const ModalSolution& near, const ModalSolution& at);

}  // namespace ringid

#endif  // RINGID_MODEL_MODAL_H_
