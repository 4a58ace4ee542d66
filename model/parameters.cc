#include "model/parameters.h"

#include <cmath>
#include <limits>

namespace ringid {
namespace {

const std::array<ParameterInfo, kNumParams> kCatalogue = {{
#define RINGID_INFO(name, unit, domain, group, text) \
  {#name, unit, Domain::domain, Group::group, text},
    RINGID_PARAMETERS(RINGID_INFO)
#undef RINGID_INFO
}};

}  // namespace

const ParameterInfo& Info(Param p) { return kCatalogue[static_cast<int>(p)]; }

std::optional<Param> ParseParam(const std::string& name) {
  for (int i = 0; i < kNumParams; ++i) {
    if (name == kCatalogue[i].name) return ParamAt(i);
  }
  return std::nullopt;
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

}  // namespace ringid
