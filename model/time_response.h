// The model's response over time (contract §11): the linear system rolling
// at speed as a state space, the slip lags' states beside the coordinates,
// driven by forces on x_b, z_b and y_b, discretised exactly with the inputs
// held first-order (linear between grid points); and the response to
// rolling over an obstacle.
#ifndef RINGID_MODEL_TIME_RESPONSE_H_
#define RINGID_MODEL_TIME_RESPONSE_H_

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "model/obstacle.h"
#include "model/rigid_ring_model.h"

namespace ringid {

// §11's outputs: the five axle channels (N, N m), then the rim's spin rate
// theta_a' (rad/s).
inline constexpr int kNumTimeOutputs = kNumAxleChannels + 1;
inline constexpr int kRimSpeedOutput = kNumAxleChannels;
// The outputs by name: the axle channels' (model/names.h), then "rim_speed".
const char* TimeOutputName(int output);
std::optional<int> ParseTimeOutput(const std::string& name);
// "axle_force_x, ..., rim_speed".
std::string TimeOutputChoices();

// x' = A x + B u, y = C x: x = [q, q', zeta] over the active coordinates and
// the lags (at speed; standing, K's contact stiffness stands for them);
// u = [F_x on x_b, F_z on z_b, F_y on y_b] (N); y as kNumTimeOutputs.
struct StateSpace {
  Eigen::MatrixXd A, B, C;
  Eigen::RowVectorXd z_b;  // the belt's vertical displacement (down) from x
};

// The state space of p rolling at speed_m_s (docs/rolling.md: sigma zeta' +
// V zeta = -d^T q' + V e^T q, the force K zeta through f). False with why
// where the mass matrix is singular.
bool RollingStateSpace(const RigidRingModel& model, const Parameters& p, double speed_m_s,
                       StateSpace* s, std::string* why);

// y at the grid times t (increasing, from the state x0 at t[0]: zero
// where empty) for the inputs u (3 x t.size()) linear between them:
// x_{k+1} = Phi x_k + G0 u_k + G1 (u_{k+1} - u_k) / dt from the exponential
// of the augmented matrix [[A, B, 0], [0, 0, I], [0, 0, 0]] dt, exact for
// such inputs. Steps of one length share one exponential.
Eigen::MatrixXd SimulateHeld(const StateSpace& s, const std::vector<double>& t,
                             const Eigen::MatrixXd& u, const Eigen::VectorXd& x0 = {});

// Rolling at speed_m_s (kSlowestRoll to kFastestRoll) over `profile` from X =
// position_at_t0_m at t = 0 (§11): the forces u = [-F_cz0 beta, -k_cz w,
// -F_cz0 beta_x] at X = position_at_t0_m + V t, held first-order on a grid
// through the sample times with steps of at most kTravelStep of travel
// where a cam reaches the profile (Reach; elsewhere the forces are 0 and
// the grid steps from sample to sample), at most kMostSteps. From rest at t = 0 (`reaches_at_t0` says where a cam already
// reaches the profile there: simulate refuses that, a fit warns), or for
// `lugs` the periodic steady state about the forces' mean (the mean's static
// response left out: §11 reports it apart).
inline constexpr double kTravelStep = 1e-3;  // m
inline constexpr double kSlowestRoll = 1e-3;  // m/s
inline constexpr long kMostSteps = 10'000'000;
// The most pieces of the profile a run visits (PieceEvaluations times its
// grid's points): a few seconds.
inline constexpr double kMostPieceEvaluations = 2e8;
inline constexpr double kFastestRoll = 200;  // m/s
// The tandem cam of p: a_e, b_e, c_e, l_s.
TandemCam CamOf(const Parameters& p);
struct ObstacleRun {
  double speed_m_s = 0;
  ObstacleProfile profile;
  TandemCam cam;
  double position_at_t0_m = 0;
  std::vector<double> times_s;  // increasing, >= 0
};
// The response, and §11's validity: the contact force F_cz0 + k_cz (z_b + w)
// over the grid (for lugs about the mean: F_cz0 is then the mean load on
// them), at its lowest (the tire leaves the road where it is not positive)
// and where its change |k_cz (z_b + w)| / F_cz0 is largest (§11 warns above
// 0.3).
struct ObstacleResult {
  Eigen::MatrixXd y;  // kNumTimeOutputs x the samples
  double lowest_contact_force_n = 0, lowest_at_s = 0;
  double largest_load_change = 0, largest_at_s = 0;
  bool reaches_at_t0 = false;  // position_at_t0_m > FirstContact (not lugs)
};
// False with why naming what is wrong.
bool ObstacleResponse(const RigidRingModel& model, const Parameters& p, const ObstacleRun& run,
                      ObstacleResult* result, std::string* why);

}  // namespace ringid

#endif  // RINGID_MODEL_TIME_RESPONSE_H_
