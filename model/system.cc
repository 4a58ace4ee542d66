#include "model/system.h"

namespace ringid {
namespace {
int I(Dof d) { return static_cast<int>(d); }
}  // namespace

MechanicalSystem::MechanicalSystem() {
  M_.setZero();
  C_.setZero();
  K_.setZero();
  for (auto& k : K_label_) k.setZero();
  active_.fill(false);
  for (int i = 0; i <= I(Dof::kPsiB); ++i) active_[i] = true;
}

void MechanicalSystem::AddMass(Dof dof, double m) { M_(I(dof), I(dof)) += m; }

void MechanicalSystem::AddSpring(std::optional<ModeLabel> owner, double k,
                                 Deformation d) {
  for (const auto& [a, ca] : d) {
    for (const auto& [b, cb] : d) {
      const double v = k * ca * cb;
      K_(I(a), I(b)) += v;
      if (owner) K_label_[static_cast<int>(*owner)](I(a), I(b)) += v;
    }
  }
}

void MechanicalSystem::AddDamper(double c, Deformation d) {
  for (const auto& [a, ca] : d) {
    for (const auto& [b, cb] : d) C_(I(a), I(b)) += c * ca * cb;
  }
}

void MechanicalSystem::AddStiffness(std::optional<ModeLabel> owner, Dof row,
                                    Dof col, double v) {
  K_(I(row), I(col)) += v;
  if (owner) K_label_[static_cast<int>(*owner)](I(row), I(col)) += v;
}

void MechanicalSystem::AddVelocityCoupling(Dof row, Dof col, double v) {
  C_(I(row), I(col)) += v;
}

void MechanicalSystem::AddSlipLag(SlipLag lag) {
  const double k = lag.stiffness / lag.relaxation_length;
  for (const auto& [a, fa] : lag.force) {
    for (const auto& [b, db] : lag.velocity) {
      const double v = k * fa * db;
      K_(I(a), I(b)) += v;
      K_label_[static_cast<int>(lag.owner)](I(a), I(b)) += v;
    }
  }
  lags_.push_back(std::move(lag));
}

}  // namespace ringid
