// M q'' + C q' + K q = 0 over every degree of freedom of names.h, built element
// by element so that each label knows the stiffness that carries it.
#ifndef RINGID_MODEL_SYSTEM_H_
#define RINGID_MODEL_SYSTEM_H_

#include <array>
#include <initializer_list>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "model/names.h"

namespace ringid {

class MechanicalSystem {
 public:
  using Matrix = Eigen::Matrix<double, kNumDofs, kNumDofs>;
  using Deformation = std::initializer_list<std::pair<Dof, double>>;
  using Combination = std::vector<std::pair<Dof, double>>;

  // Eq. (5) linearised about free rolling at speed V (docs/rolling.md): the
  // slip zeta of one contact direction obeys sigma zeta' + V zeta =
  // -d^T q' + V e^T q, and its force K zeta acts on q through f. At
  // standstill zeta = -d^T q / sigma: the stiffness (K / sigma) f d^T.
  struct SlipLag {
    ModeLabel owner;
    double stiffness;           // K_c
    double relaxation_length;   // sigma_c
    Combination force;          // f
    Combination velocity;       // d
    Combination heading;        // e
  };

  // The seven belt and rim degrees of freedom active; the hub held rigid.
  MechanicalSystem();

  void Activate(Dof dof) { active_[static_cast<int>(dof)] = true; }
  bool active(Dof dof) const { return active_[static_cast<int>(dof)]; }

  void AddMass(Dof dof, double m);
  // A spring k on the deformation d = sum coef * q: adds k d d^T to K and to the
  // stiffness of `owner`, the label named after the element it deforms.
  void AddSpring(std::optional<ModeLabel> owner, double k, Deformation d);
  void AddDamper(double c, Deformation d);
  // A single, possibly unsymmetric, stiffness term (the trail coupling of S).
  void AddStiffness(std::optional<ModeLabel> owner, Dof row, Dof col, double v);
  void AddVelocityCoupling(Dof row, Dof col, double v);  // C(row, col) += v
  // Adds the lag, and its standstill stiffness to K() and to its owner: K()
  // is always the standing stiffness; at speed the lag's states replace it.
  void AddSlipLag(SlipLag lag);

  // The forward speed of free rolling; 0 at standstill.
  void set_speed(double speed_m_s) { speed_ = speed_m_s; }
  double speed() const { return speed_; }
  const std::vector<SlipLag>& lags() const { return lags_; }

  const Matrix& M() const { return M_; }
  const Matrix& C() const { return C_; }
  const Matrix& K() const { return K_; }
  const Matrix& K_label(ModeLabel l) const {
    return K_label_[static_cast<int>(l)];
  }

 private:
  Matrix M_, C_, K_;
  std::array<Matrix, kNumLabels> K_label_;
  std::array<bool, kNumDofs> active_;
  std::vector<SlipLag> lags_;
  double speed_ = 0;
};

}  // namespace ringid

#endif  // RINGID_MODEL_SYSTEM_H_
