#include "model/names.h"

#include <array>

namespace ringid {
namespace {

// The home degree of freedom of each label (see LabelHome).
constexpr std::array<Dof, kNumLabels> kLabelHomes = {
    Dof::kThetaA, Dof::kThetaB, Dof::kZb, Dof::kXb,
    Dof::kGammaB, Dof::kPsiB, Dof::kYb,
    Dof::kXa, Dof::kZa, Dof::kYa};

}  // namespace

Plane DofPlane(Dof dof) {
  const int i = static_cast<int>(dof);
  if (i <= 3) return Plane::kInPlane;
  if (i <= 6) return Plane::kOutOfPlane;
  return Plane::kHub;
}

Dof LabelHome(ModeLabel label) { return kLabelHomes[static_cast<int>(label)]; }

Plane LabelPlane(ModeLabel label) { return DofPlane(LabelHome(label)); }

}  // namespace ringid
