// The lug orders against the modes over speed (issue 23, item 3): where the
// k-th lug order, k lugs V / (2 pi r_e0), meets a mode's frequency.
#ifndef RINGID_MODEL_CAMPBELL_H_
#define RINGID_MODEL_CAMPBELL_H_

#include <vector>

#include "model/archive.h"
#include "model/rigid_ring_model.h"

namespace ringid {

struct CriticalSpeed {
  int order = 1;
  ModeLabel label = ModeLabel::kVertical;
  double speed_m_s = 0;
  double frequency_hz = 0;  // the mode's, which the order meets there
  double damping_ratio = 0;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("order", &order);
    a->Visit("label", &label);
    a->Visit("speed_m_s", &speed_m_s);
    a->Visit("frequency_hz", &frequency_hz);
    a->Visit("damping_ratio", &damping_ratio);
  }
};

// The frequency of lug order `order` at speed V: order lugs V / (2 pi r_e0).
double LugOrderHz(int order, int lugs_per_revolution, double r_e0, double speed_m_s);

// Every crossing of a lug order with a mode between consecutive `speeds`
// (ascending), found where their difference changes sign and refined by
// bisection to 1e-6 of the interval, ordered by speed. The orders tried are
// those that reach the highest mode frequency within the speeds, at most
// max_order (a slowest speed near 0 asks for hundreds: order k meets a mode
// f at V = 2 pi r_e0 f / (k lugs)).
std::vector<CriticalSpeed> CriticalSpeeds(const ModalModel& model, const Parameters& p,
                                          int lugs_per_revolution, const std::vector<double>& speeds,
                                          int max_order);
// The largest max_order: it bounds the work (a bisection per order, mode and
// interval between speeds).
inline constexpr int kMaxOrders = 200;

}  // namespace ringid

#endif  // RINGID_MODEL_CAMPBELL_H_
