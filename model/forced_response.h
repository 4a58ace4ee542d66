// The model's frequency response from the lug forces at the contact to what
// the held axle carries, standing or rolling (contract §8, docs/forces.md):
// the same assembled system as the modes, effects and slip states included.
#ifndef RINGID_MODEL_FORCED_RESPONSE_H_
#define RINGID_MODEL_FORCED_RESPONSE_H_

#include <complex>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "model/frequency_response.h"  // Complex
#include "model/rigid_ring_model.h"

namespace ringid {

// H(channel, force): the axle's response per unit lug force (N/N, N m/N).
using AxleResponseMatrix = Eigen::Matrix<Complex, kNumAxleChannels, kNumLugForces>;

// Eq. (F2): the generalised forces of unit lug forces at the contact point,
// one column per LugForce over Dof (F_x as F_cx, F_y as F_cy); T a ceres::Jet
// for their derivatives (P: ParameterArray<T>).
template <class T, class P>
Eigen::Matrix<T, kNumDofs, kNumLugForces> LugForceColumns(const P& p) {
  Eigen::Matrix<T, kNumDofs, kNumLugForces> B;
  B.setConstant(T(0.0));
  auto at = [&](Dof d, LugForce f) -> T& { return B(static_cast<int>(d), static_cast<int>(f)); };
  at(Dof::kXb, LugForce::kFx) = T(1.0);
  at(Dof::kThetaB, LugForce::kFx) = -p[Param::r_e0];
  at(Dof::kZb, LugForce::kFz) = T(1.0);
  at(Dof::kYb, LugForce::kFy) = T(1.0);
  at(Dof::kGammaB, LugForce::kFy) = -p[Param::r_l0];
  at(Dof::kPsiB, LugForce::kFy) = -p[Param::t_0];
  return B;
}
inline Eigen::Matrix<double, kNumDofs, kNumLugForces> LugForceColumns(const Parameters& p) {
  return LugForceColumns<double>(p);
}

// The degrees of freedom active in `s`, in Dof order.
std::vector<int> ActiveDofs(const MechanicalSystem& s);

// H at `frequency_hz` (> 0) for parameters p rolling at speed_m_s (0:
// standing): model/frequency_response.h with the contact forces in and the
// channels out. False, with why, where the system cannot respond there
// (a singular dynamic stiffness: an undamped resonance).
bool AxleResponse(const RigidRingModel& model, const Parameters& p, double speed_m_s,
                  double frequency_hz, AxleResponseMatrix* H, std::string* why);

// The rigid ring moves the belt as a whole; above its modes the belt's
// bending modes, which it lacks, take over. It is taken to hold below
// kModelRangeFactor times the highest of the tire's standing modes under p
// (the hub's aside): the rule and why, docs/forces.md §3. NaN where the
// model cannot be solved.
inline constexpr double kModelRangeFactor = 1.5;
double ModelValidBelowHz(const RigidRingModel& model, const Parameters& p);

}  // namespace ringid

#endif  // RINGID_MODEL_FORCED_RESPONSE_H_
