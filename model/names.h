// Degrees of freedom, mode labels and planes: the names of contract section 1.
#ifndef RINGID_MODEL_NAMES_H_
#define RINGID_MODEL_NAMES_H_

#include <optional>
#include <string>

namespace ringid {

// Degrees of freedom of the rigid-ring model. The hub translations exist in
// every assembled system but are held at zero unless an effect frees them.
enum class Dof : int {
  kXb = 0, kZb, kThetaA, kThetaB,  // in-plane, eq. (12)
  kYb, kGammaB, kPsiB,             // out-of-plane, eq. (15)
  kXa, kZa, kYa,                   // hub translation (hub_compliance)
};
inline constexpr int kNumDofs = 10;

enum class Plane : int { kInPlane = 0, kOutOfPlane, kHub };

// Physical modes. Each label has one "home" degree of freedom (LabelHome), so
// a block of k coupled degrees of freedom offers exactly k labels.
enum class ModeLabel : int {
  kRotationInPhase = 0, kRotationAntiPhase, kVertical, kLongitudinal,
  kCamber, kYaw, kLateral,
  kHubLongitudinal, kHubVertical, kHubLateral,
};
inline constexpr int kNumLabels = 10;

const char* DofName(Dof dof);
std::optional<Dof> ParseDof(const std::string& name);
Plane DofPlane(Dof dof);

const char* LabelName(ModeLabel label);
std::optional<ModeLabel> ParseLabel(const std::string& name);
Plane LabelPlane(ModeLabel label);
Dof LabelHome(ModeLabel label);

const char* PlaneName(Plane plane);

}  // namespace ringid

#endif  // RINGID_MODEL_NAMES_H_
