// The model's frequency response functions (contract §9): H(iω) from any
// generalised input (a point force, a combination of coordinates, §8's
// contact forces) to any output (a point's or a combination's displacement,
// velocity or acceleration, §8's axle channels), standing or rolling, every
// effect and slip state included, with exact derivatives with respect to the
// parameters: dH = dG X + Y dB - Y dD X, X = D^-1 B, Y = G D^-1, through the
// dynamic stiffness D of docs/forces.md eq. (F1).
#ifndef RINGID_MODEL_FREQUENCY_RESPONSE_H_
#define RINGID_MODEL_FREQUENCY_RESPONSE_H_

#include <complex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "model/rigid_ring_model.h"

namespace ringid {

using Complex = std::complex<double>;

// Coefficients on the coordinates: an input's generalised forces per newton,
// or an output's motion per unit of each coordinate.
using Coordinates = std::vector<std::pair<Dof, double>>;

// One of §8's contact forces (eq. F2: LugForceColumns), or generalised forces.
struct ResponseInput {
  std::optional<LugForce> contact;
  Coordinates coordinates;  // where not a contact force
  // A point on the rim: its hub terms (x_a, z_a, y_a) act only where the
  // model frees the hub (contract §9); elsewhere every coordinate must exist.
  bool on_rim = false;
};

// One of §8's axle channels (eq. F3: hub held, N or N m per N), or a
// combination of coordinates differentiated `order` times in time (0
// displacement, 1 velocity, 2 acceleration: a factor (iω)^order).
struct ResponseOutput {
  std::optional<AxleChannel> channel;
  Coordinates coordinates;  // where not a channel
  int order = 0;
  bool on_rim = false;  // as ResponseInput's
};

struct ResponseRequest {
  std::vector<ResponseInput> inputs;
  std::vector<ResponseOutput> outputs;
  std::vector<std::pair<int, int>> pairs;  // (output, input) of each function wanted
  std::vector<double> frequencies_hz;      // each > 0
};

struct ResponseResult {
  bool ok = false;
  std::string error;  // why not, where !ok
  // H(line, function): the output's phasor per unit input phasor (§8's
  // convention q(t) = Re(Q e^{iωt})).
  Eigen::MatrixXcd H;
  // With derivatives, dH(function * lines + line, k) = dH / d(catalogue
  // parameter params[k]): a row per value, function-major as a fit's
  // residuals, its parameters side by side.
  Eigen::Matrix<std::complex<double>, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> dH;
};

// At parameters p (every one the model reads set), rolling at speed_m_s (0:
// standing). With `params`, the exact derivatives with respect to those
// catalogue parameters (by index). Not ok where an input or output acts on a
// coordinate the model lacks (the hub's translations without
// hub_compliance), or where D is singular at a line (an undamped resonance).
ResponseResult FrequencyResponse(const ModalModel& model, const Parameters& p, double speed_m_s,
                                 const ResponseRequest& request,
                                 const std::vector<int>* params = nullptr);
// The same into `out`, whose storage is reused where it has the size: a
// fit's Jacobian of a hammer test holds megabytes of dH.
void FrequencyResponse(const ModalModel& model, const Parameters& p, double speed_m_s,
                       const ResponseRequest& request, const std::vector<int>* params,
                       ResponseResult* out);

// The coordinate of `c` the model lacks at any size of its effects, if any
// (the hub's translations without hub_compliance); on the rim the hub's are
// not missed.
std::optional<Dof> MissingCoordinate(const ModalModel& model, const Coordinates& c,
                                     bool on_rim = false);

}  // namespace ringid

#endif  // RINGID_MODEL_FREQUENCY_RESPONSE_H_
