// The excitation of a lugged tread from its geometry (contract §11): a `lugs`
// profile rolled at speed, its effective height, slope and banking as
// Fourier series over one pitch, the forces they put on the ring per lug
// order and the axle's response to each.
#ifndef RINGID_MODEL_LUG_EXCITATION_H_
#define RINGID_MODEL_LUG_EXCITATION_H_

#include <array>
#include <complex>
#include <string>
#include <vector>

#include "model/campbell.h"
#include "model/names.h"
#include "model/obstacle.h"
#include "model/rigid_ring_model.h"
#include "model/time_response.h"

namespace ringid {

// Order k at k V / P Hz. A quantity is f(t) = mean + sum_k Re(f_k e^{i 2 pi k V t / P}),
// the contact centre at X = V t (a lug of the centre lane centred at X = 0).
struct LugOrderExcitation {
  int order = 0;
  double frequency_hz = 0;
  // -F_cz0 beta on x_b, -k_cz w on z_b, -F_cz0 beta_x on y_b (N), §11's inputs,
  // named by LugForce (model/names.h).
  std::array<std::complex<double>, 3> force{};
  // The five axle channels (N, N m) and rim_speed (rad/s), time_response.h's order.
  std::array<std::complex<double>, kNumTimeOutputs> response{};

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("order", &order);
    a->Visit("frequency_hz", &frequency_hz);
    a->Group("forces", [&](auto* g) {
      for (int i = 0; i < 3; ++i) g->Visit(ToString(static_cast<LugForce>(i)), &force[i]);
    });
    a->Group("response", [&](auto* g) {
      for (int c = 0; c < kNumTimeOutputs; ++c) g->Visit(TimeOutputName(c), &response[c]);
    });
  }
};
struct LugExcitation {
  double speed_m_s = 0;
  std::array<double, 3> mean_force{};  // the forces' mean: a static offset, apart
  std::vector<LugOrderExcitation> orders;  // 1 .. max_order

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("speed_m_s", &speed_m_s);
    a->Group("mean_forces", [&](auto* g) {
      for (int i = 0; i < 3; ++i) g->Visit(ToString(static_cast<LugForce>(i)), &mean_force[i]);
    });
    a->Visit("orders", &orders);
  }
};

// The coefficients from the periodic trapezoid rule on kLugSamples points per
// pitch or one per kTravelStep / 4, whichever is more; the response H(i w) f
// from the rolling state space; max_order at most kMaxOrders (campbell.h).
// False with why.
inline constexpr int kLugSamples = 4096;
bool LugExcitationOf(const RigidRingModel& model, const Parameters& p,
                     const ObstacleProfile& lugs, double speed_m_s, int max_order,
                     LugExcitation* out, std::string* why);

}  // namespace ringid

#endif  // RINGID_MODEL_LUG_EXCITATION_H_
