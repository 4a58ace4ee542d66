// Degrees of freedom, mode labels and planes: the names of docs/conventions.md §1.
#ifndef RINGID_MODEL_NAMES_H_
#define RINGID_MODEL_NAMES_H_

#include <array>
#include <optional>
#include <string>

#include "model/enum_names.h"

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

template <>
struct EnumNames<Dof> {
  static constexpr std::array<const char*, kNumDofs> kNames = {
      "x_b", "z_b", "theta_a", "theta_b", "y_b", "gamma_b", "psi_b",
      "x_a", "z_a", "y_a"};
};
template <>
struct EnumNames<ModeLabel> {
  static constexpr std::array<const char*, kNumLabels> kNames = {
      "rotation_in_phase", "rotation_anti_phase", "vertical", "longitudinal",
      "camber", "yaw", "lateral",
      "hub_longitudinal", "hub_vertical", "hub_lateral"};
};
template <>
struct EnumNames<Plane> {
  static constexpr std::array<const char*, 3> kNames = {"in_plane", "out_of_plane", "hub"};
};

// The lug forces at the contact point and the axle outputs of a drum test
// (contract §8; docs/forces.md).
enum class LugForce : int { kFx = 0, kFz, kFy };
inline constexpr int kNumLugForces = 3;
template <>
struct EnumNames<LugForce> {
  static constexpr std::array<const char*, kNumLugForces> kNames = {"F_x", "F_z", "F_y"};
};
enum class AxleChannel : int { kForceX = 0, kForceZ, kForceY, kMomentX, kMomentZ };
inline constexpr int kNumAxleChannels = 5;
template <>
struct EnumNames<AxleChannel> {
  static constexpr std::array<const char*, kNumAxleChannels> kNames = {
      "axle_force_x", "axle_force_z", "axle_force_y", "axle_moment_x", "axle_moment_z"};
};

// The directions of a static stiffness at the contact (contract §10); the
// assembly records the contact element of each (BasicSystem::AddContact).
enum class StaticDirection : int { kVertical = 0, kLongitudinal, kLateral };
inline constexpr int kNumStaticDirections = 3;
template <>
struct EnumNames<StaticDirection> {
  static constexpr std::array<const char*, kNumStaticDirections> kNames = {
      "vertical", "longitudinal", "lateral"};
};

inline const char* DofName(Dof dof) { return ToString(dof); }
inline std::optional<Dof> ParseDof(const std::string& name) { return FromString<Dof>(name); }
Plane DofPlane(Dof dof);

inline const char* LabelName(ModeLabel label) { return ToString(label); }
inline std::optional<ModeLabel> ParseLabel(const std::string& name) {
  return FromString<ModeLabel>(name);
}
Plane LabelPlane(ModeLabel label);
Dof LabelHome(ModeLabel label);

inline const char* PlaneName(Plane plane) { return ToString(plane); }

}  // namespace ringid

#endif  // RINGID_MODEL_NAMES_H_
