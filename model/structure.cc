#include "model/structure.h"

#include <vector>

namespace ringid {
namespace {

void AddRow(const ParameterJet& v, std::vector<ParameterJet>* rows) {
  if (v.a != 0.0 || !v.v.isZero()) rows->push_back(v);
}

Eigen::MatrixXd Derivatives(const std::vector<ParameterJet>& rows) {
  Eigen::MatrixXd d(rows.size(), kNumParams);
  for (size_t r = 0; r < rows.size(); ++r) d.row(r) = rows[r].v.transpose();
  return d;
}

}  // namespace

SystemDerivatives Differentiate(const ModalModel& model, const Parameters& p, double speed) {
  const BasicSystem<ParameterJet> s = model.Assemble(Seeded(p), speed);
  std::vector<ParameterJet> scaling, invariant;
  for (const auto* m : {&s.M(), &s.C(), &s.K()}) {
    for (int a = 0; a < kNumDofs; ++a) {
      for (int b = 0; b < kNumDofs; ++b) {
        if (s.active(static_cast<Dof>(a)) && s.active(static_cast<Dof>(b))) AddRow((*m)(a, b), &scaling);
      }
    }
  }
  if (speed > 0) {
    for (const auto& lag : s.lags()) {
      const ParameterJet rate = lag.stiffness / lag.relaxation_length;
      for (const auto& [a, f] : lag.force) {
        for (const auto& [b, d] : lag.velocity) AddRow(rate * f * d, &scaling);
        for (const auto& [b, e] : lag.heading) AddRow(rate * speed * f * e, &scaling);
      }
      invariant.push_back(speed / lag.relaxation_length);
    }
  }
  SystemDerivatives out;
  out.scaling = Derivatives(scaling);
  out.scaling_value.resize(scaling.size());
  for (size_t r = 0; r < scaling.size(); ++r) out.scaling_value[r] = scaling[r].a;
  out.invariant = Derivatives(invariant);
  return out;
}

}  // namespace ringid
