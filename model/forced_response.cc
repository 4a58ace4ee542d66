#include "model/forced_response.h"

#include <algorithm>
#include <cmath>

#include "model/frequency_response.h"

namespace ringid {

std::vector<int> ActiveDofs(const MechanicalSystem& s) {
  std::vector<int> dofs;
  for (int d = 0; d < kNumDofs; ++d) {
    if (s.active(static_cast<Dof>(d))) dofs.push_back(d);
  }
  return dofs;
}

bool AxleResponse(const RigidRingModel& model, const Parameters& p, double speed_m_s,
                  double frequency_hz, AxleResponseMatrix* H, std::string* why) {
  ResponseRequest request;
  request.frequencies_hz = {frequency_hz};
  for (int f = 0; f < kNumLugForces; ++f) request.inputs.push_back({static_cast<LugForce>(f), {}});
  for (int c = 0; c < kNumAxleChannels; ++c) {
    request.outputs.push_back({static_cast<AxleChannel>(c), {}, 0});
    for (int f = 0; f < kNumLugForces; ++f) request.pairs.push_back({c, f});
  }
  const ResponseResult r = FrequencyResponse(model, p, speed_m_s, request);
  if (!r.ok) {
    *why = r.error;
    return false;
  }
  for (int c = 0; c < kNumAxleChannels; ++c) {
    for (int f = 0; f < kNumLugForces; ++f) (*H)(c, f) = r.H(0, c * kNumLugForces + f);
  }
  return true;
}

double ModelValidBelowHz(const RigidRingModel& model, const Parameters& p) {
  const ModalSolution s = model.Solve(p);
  double highest = 0;
  for (const Mode& m : s.modes) {
    if (LabelPlane(m.label) != Plane::kHub) highest = std::max(highest, m.frequency_hz);
  }
  return s.ok && highest > 0 ? kModelRangeFactor * highest : NAN;
}

}  // namespace ringid
