// The model's frequency response from the lug forces at the contact to what
// the held axle carries, standing or rolling (contract §8, docs/forces.md):
// the same assembled system as the modes, effects and slip states included.
#ifndef RINGID_MODEL_FORCED_RESPONSE_H_
#define RINGID_MODEL_FORCED_RESPONSE_H_

#include <complex>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "model/rigid_ring_model.h"

namespace ringid {

using Complex = std::complex<double>;
// H(channel, force): the axle's response per unit lug force (N/N, N m/N).
using AxleResponseMatrix = Eigen::Matrix<Complex, kNumAxleChannels, kNumLugForces>;

// Eq. (F2): the generalised forces of unit lug forces at the contact point,
// one column per LugForce over Dof (F_x as F_cx, F_y as F_cy).
Eigen::Matrix<double, kNumDofs, kNumLugForces> LugForceColumns(const Parameters& p);

// Eq. (F1): the dynamic stiffness D(s) over `dofs` (the active ones), with
// the slip states eliminated; D(s) q = f for q(t) = Re(q e^{st}).
Eigen::MatrixXcd DynamicStiffness(const MechanicalSystem& s, const std::vector<int>& dofs,
                                  Complex lambda);

// The degrees of freedom active in `s`, in Dof order.
std::vector<int> ActiveDofs(const MechanicalSystem& s);

// H at `frequency_hz` (> 0) for parameters p rolling at speed_m_s (0:
// standing). False, with why, where the system cannot respond there
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
