#include "model/names.h"

#include <array>

namespace ringid {
namespace {

constexpr std::array<const char*, kNumDofs> kDofNames = {
    "x_b", "z_b", "theta_a", "theta_b", "y_b", "gamma_b", "psi_b",
    "x_a", "z_a", "y_a"};

constexpr std::array<const char*, kNumLabels> kLabelNames = {
    "rotation_in_phase", "rotation_anti_phase", "vertical", "longitudinal",
    "camber", "yaw", "lateral",
    "hub_longitudinal", "hub_vertical", "hub_lateral"};

// The home degree of freedom of each label (see LabelHome).
constexpr std::array<Dof, kNumLabels> kLabelHomes = {
    Dof::kThetaA, Dof::kThetaB, Dof::kZb, Dof::kXb,
    Dof::kGammaB, Dof::kPsiB, Dof::kYb,
    Dof::kXa, Dof::kZa, Dof::kYa};

}  // namespace

const char* DofName(Dof dof) { return kDofNames[static_cast<int>(dof)]; }

std::optional<Dof> ParseDof(const std::string& name) {
  for (int i = 0; i < kNumDofs; ++i) {
    if (name == kDofNames[i]) return static_cast<Dof>(i);
  }
  return std::nullopt;
}

Plane DofPlane(Dof dof) {
  const int i = static_cast<int>(dof);
  if (i <= 3) return Plane::kInPlane;
  if (i <= 6) return Plane::kOutOfPlane;
  return Plane::kHub;
}

const char* LabelName(ModeLabel label) {
  return kLabelNames[static_cast<int>(label)];
}

std::optional<ModeLabel> ParseLabel(const std::string& name) {
  for (int i = 0; i < kNumLabels; ++i) {
    if (name == kLabelNames[i]) return static_cast<ModeLabel>(i);
  }
  return std::nullopt;
}

Dof LabelHome(ModeLabel label) { return kLabelHomes[static_cast<int>(label)]; }

Plane LabelPlane(ModeLabel label) { return DofPlane(LabelHome(label)); }

const char* PlaneName(Plane plane) {
  switch (plane) {
    case Plane::kInPlane: return "in_plane";
    case Plane::kOutOfPlane: return "out_of_plane";
    case Plane::kHub: return "hub";
  }
  return "unknown";
}

}  // namespace ringid
