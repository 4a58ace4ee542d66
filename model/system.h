// M q'' + C q' + K q = 0 over every degree of freedom of names.h, built element
// by element so that each label knows the stiffness that carries it.
#ifndef RINGID_MODEL_SYSTEM_H_
#define RINGID_MODEL_SYSTEM_H_

#include <array>
#include <initializer_list>
#include <optional>
#include <utility>

#include <Eigen/Core>

#include "model/names.h"

namespace ringid {

class MechanicalSystem {
 public:
  using Matrix = Eigen::Matrix<double, kNumDofs, kNumDofs>;
  using Deformation = std::initializer_list<std::pair<Dof, double>>;

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
};

}  // namespace ringid

#endif  // RINGID_MODEL_SYSTEM_H_
