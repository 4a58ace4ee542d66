#include "model/parameters.h"

#include <cmath>
#include <limits>

namespace ringid {
namespace {

const std::array<ParameterInfo, kNumParams> kCatalogue = {{
#define RINGID_INFO(name, unit, domain, group, text) \
  {unit, Domain::domain, Group::group, text},
    RINGID_PARAMETERS(RINGID_INFO)
#undef RINGID_INFO
}};

}  // namespace

const ParameterInfo& Info(Param p) { return kCatalogue[static_cast<int>(p)]; }

const std::vector<Param>& CamParameters() {
  static const std::vector<Param> cam = [] {
    std::vector<Param> out;
    for (int i = 0; i < kNumParams; ++i) {
      if (Info(ParamAt(i)).group == Group::kEnvelope) out.push_back(ParamAt(i));
    }
    return out;
  }();
  return cam;
}

double TypicalScale(Param p) {
  switch (p) {
    case Param::dk_bz: return 1e4;      // N/m, a few % of k_bz
    case Param::dk_bpsi: return 1e2;    // N m/rad
    case Param::s_h: return 1e-7;       // m/N: a hub on 1e7 N/m springs
    case Param::k_cpsi: return 1e2;     // N m/rad
    case Param::k_atheta: return 1e3;   // N m/rad
    case Param::dm: return 0.1;         // kg
    case Param::k_xy: return 1e4;       // N/m
    default: return 1.0;
  }
}

Parameters::Parameters() {
  for (int i = 0; i < kNumParams; ++i) {
    v_[i] = kCatalogue[i].group == Group::kEffect
                ? 0.0
                : std::numeric_limits<double>::quiet_NaN();
  }
  v_[static_cast<int>(Param::m_a)] = std::numeric_limits<double>::quiet_NaN();
}

bool Parameters::IsSet(Param p) const { return std::isfinite((*this)[p]); }

double SidewallFrequencyHz(const SidewallElement& e, const Parameters& p) {
  return std::sqrt(p[e.stiffness] / p[e.inertia]) / (2 * M_PI);
}

double SidewallDampingRatio(const SidewallElement& e, const Parameters& p) {
  return p[e.damper] / (2 * std::sqrt(p[e.stiffness] * p[e.inertia]));
}

double SidewallStiffness(const SidewallElement& e, double hz, const Parameters& p) {
  const double w = 2 * M_PI * hz;
  return p[e.inertia] * (w * w);
}

double SidewallDamper(const SidewallElement& e, double zeta, const Parameters& p) {
  return 2 * zeta * std::sqrt(p[e.stiffness] * p[e.inertia]);
}

ParameterArray<ParameterJet> Seeded(const Parameters& p) {
  ParameterArray<ParameterJet> q;
  for (int i = 0; i < kNumParams; ++i) q[ParamAt(i)] = ParameterJet(p[ParamAt(i)], i);
  return q;
}

}  // namespace ringid
