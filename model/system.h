// M q'' + C q' + K q = 0 over every degree of freedom of names.h, built element
// by element so that each label knows the stiffness that carries it. The
// scalar is double, or a ceres::Jet where the exact derivatives of the
// matrices with respect to the parameters are wanted (model/structure.h).
#ifndef RINGID_MODEL_SYSTEM_H_
#define RINGID_MODEL_SYSTEM_H_

#include <array>
#include <initializer_list>
#include <optional>
#include <type_traits>
#include <utility>  // std::pair
#include <vector>

#include <Eigen/Core>

#include "model/names.h"

namespace ringid {

// One degree of freedom with its coefficient in a deformation.
template <class T>
struct Term {
  template <class C>
  Term(Dof d, const C& c) : dof(d), coef(c) {}  // NOLINT: {Dof, 1} reads as a term
  Dof dof;
  T coef;
};

template <class T>
class BasicSystem {
 public:
  using Scalar = T;
  using Matrix = Eigen::Matrix<T, kNumDofs, kNumDofs>;
  using Deformation = std::initializer_list<Term<T>>;
  using Combination = std::vector<Term<T>>;

  // Eq. (5) linearised about free rolling at speed V (docs/rolling.md): the
  // slip zeta of one contact direction obeys sigma zeta' + V zeta =
  // -d^T q' + V e^T q, and its force K zeta acts on q through f. At
  // standstill zeta = -d^T q / sigma: the stiffness (K / sigma) f d^T.
  struct SlipLag {
    ModeLabel owner;
    StaticDirection direction;  // the contact it is (AddContact)
    T stiffness;           // K_c
    T relaxation_length;   // sigma_c
    Combination force;     // f
    Combination velocity;  // d
    Combination heading;   // e
  };

  // A contact element (contract §10): a spring k between the road, displaced
  // by delta in `direction`, and the tire. It carries k (delta - d^T q) and
  // acts on q through f; on the road at rest it is the stiffness k f d^T.
  // The elements of one direction share the road's delta.
  struct Contact {
    StaticDirection direction;
    T stiffness;                // k
    Combination force;          // f
    Combination displacement;   // d
  };

  // What the held axle carries (contract §8): per channel, its force as a
  // combination of displacements and of velocities, row-major over Dof.
  using AxleRows = Eigen::Matrix<T, kNumAxleChannels, kNumDofs, Eigen::RowMajor>;

  // The seven belt and rim degrees of freedom active; the hub held rigid.
  BasicSystem() {
    M_.setZero();
    C_.setZero();
    K_.setZero();
    axle_displacement_.setZero();
    axle_velocity_.setZero();
    for (Matrix& k : K_label_) k.setZero();
    active_.fill(false);
    for (int i = 0; i <= I(Dof::kPsiB); ++i) active_[i] = true;
  }

  void Activate(Dof dof) { active_[I(dof)] = true; }
  bool active(Dof dof) const { return active_[I(dof)]; }

  void AddMass(Dof dof, const T& m) { M_(I(dof), I(dof)) += m; }
  // A spring k on the deformation d = sum coef * q: adds k d d^T to K and to the
  // stiffness of `owner`, the label named after the element it deforms.
  void AddSpring(std::optional<ModeLabel> owner, const T& k, Deformation d) {
    for (const auto& [a, ca] : d) {
      for (const auto& [b, cb] : d) AddStiffness(owner, a, b, k * ca * cb);
    }
  }
  void AddDamper(const T& c, Deformation d) {
    for (const auto& [a, ca] : d) {
      for (const auto& [b, cb] : d) C_(I(a), I(b)) += c * ca * cb;
    }
  }
  // A single, possibly unsymmetric, stiffness term (the trail coupling of S).
  void AddStiffness(std::optional<ModeLabel> owner, Dof row, Dof col, const T& v) {
    K_(I(row), I(col)) += v;
    if constexpr (kLabelled) {
      if (owner) K_label_[static_cast<int>(*owner)](I(row), I(col)) += v;
    }
  }
  void AddVelocityCoupling(Dof row, Dof col, const T& v) { C_(I(row), I(col)) += v; }
  // Adds k f d^T to K and to `owner`, and records the element as the
  // contact in its direction (the static solve, model/static_stiffness.h).
  void AddContact(ModeLabel owner, Contact contact) {
    for (const auto& [a, fa] : contact.force) {
      for (const auto& [b, db] : contact.displacement) {
        AddStiffness(owner, a, b, contact.stiffness * fa * db);
      }
    }
    contacts_.push_back(std::move(contact));
  }
  // Adds the lag, and its standstill stiffness to K() and to its owner as a
  // contact (K_c / sigma_c on f, d): K() is always the standing stiffness; at
  // speed the lag's states replace it.
  void AddSlipLag(SlipLag lag) {
    AddContact(lag.owner, {lag.direction, lag.stiffness / lag.relaxation_length, lag.force,
                           lag.velocity});
    lags_.push_back(std::move(lag));
  }

  // An element joining the tire to the axle: the axle carries k d (a spring
  // on the deformation d, or a circulatory term) or c d' (a damper) in
  // `channel`, with the sign of the force or moment the element exerts on it.
  void AddToAxle(AxleChannel channel, const T& k, Deformation d) {
    for (const auto& [dof, coef] : d) axle_displacement_(I(channel), I(dof)) += k * coef;
  }
  void AddToAxleDamping(AxleChannel channel, const T& c, Deformation d) {
    for (const auto& [dof, coef] : d) axle_velocity_(I(channel), I(dof)) += c * coef;
  }
  // The axle holds the tire through a spring k on `dof` alone (a compliant
  // hub): that spring's force is the channel, whatever else joins the tire
  // to the hub.
  void HoldAxleBy(AxleChannel channel, const T& k, Dof dof) {
    held_[I(channel)] = std::make_pair(k, dof);
  }
  AxleRows axle_displacement() const {
    AxleRows rows = axle_displacement_;
    for (int c = 0; c < kNumAxleChannels; ++c) {
      if (!held_[c]) continue;
      rows.row(c).setZero();
      rows(c, I(held_[c]->second)) = held_[c]->first;
    }
    return rows;
  }
  AxleRows axle_velocity() const {
    AxleRows rows = axle_velocity_;
    for (int c = 0; c < kNumAxleChannels; ++c) {
      if (held_[c]) rows.row(c).setZero();
    }
    return rows;
  }

  // The forward speed of free rolling; 0 at standstill.
  void set_speed(double speed_m_s) { speed_ = speed_m_s; }
  double speed() const { return speed_; }
  const std::vector<SlipLag>& lags() const { return lags_; }
  const std::vector<Contact>& contacts() const { return contacts_; }

  const Matrix& M() const { return M_; }
  const Matrix& C() const { return C_; }
  const Matrix& K() const { return K_; }
  const Matrix& K_label(ModeLabel l) const { return K_label_[static_cast<int>(l)]; }

 private:
  static int I(Dof d) { return static_cast<int>(d); }
  static int I(AxleChannel c) { return static_cast<int>(c); }
  // Labels are decided on values: the derivatives (jets) need no K_label.
  static constexpr bool kLabelled = std::is_same_v<T, double>;

  Matrix M_, C_, K_;
  std::array<Matrix, kLabelled ? kNumLabels : 0> K_label_;
  std::array<bool, kNumDofs> active_;
  std::vector<SlipLag> lags_;
  std::vector<Contact> contacts_;
  double speed_ = 0;
  AxleRows axle_displacement_, axle_velocity_;
  std::array<std::optional<std::pair<T, Dof>>, kNumAxleChannels> held_;
};

using MechanicalSystem = BasicSystem<double>;

}  // namespace ringid

#endif  // RINGID_MODEL_SYSTEM_H_
