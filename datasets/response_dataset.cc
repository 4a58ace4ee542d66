#include "datasets/response_dataset.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "datasets/file_kind.h"
#include "datasets/typed_file.h"
#include "model/campbell.h"
#include "model/forced_response.h"
#include "model/spelling.h"

namespace ringid {
namespace {

using internal::ReadTyped;

// The first rule `data` breaks, as error's field and message; true for none.
class Checker {
 public:
  explicit Checker(LoadError* error) : error_(error) {}
  bool Fail(const std::string& field, const std::string& message) {
    error_->field = field;
    error_->message = message;
    return false;
  }
  bool Positive(double v, const std::string& field) {
    if (!std::isfinite(v)) return Fail(field, "must be a number");
    return v > 0 || Fail(field, "must be positive");
  }

 private:
  LoadError* error_;
};

bool Check(const ResponseDatasetFields& j, ResponseDataset* d, LoadError* error) {
  Checker c(error);
  d->name = j.name;
  if (d->name.empty()) return c.Fail("name", "must not be empty");
  d->description = j.description.value_or("");
  d->lugs_per_revolution = j.lugs_per_revolution;
  if (j.lugs_per_revolution <= 0) return c.Fail("lugs_per_revolution", "must be positive");
  if (j.conditions.empty()) return c.Fail("conditions", "must be a non-empty array");
  std::set<std::string> names;
  for (size_t i = 0; i < j.conditions.size(); ++i) {
    const ResponseConditionFields& jc = j.conditions[i];
    const std::string f = "conditions[" + std::to_string(i) + "]";
    ResponseCondition rc;
    rc.name = jc.name;
    if (!ValidConditionName(rc.name)) {
      return c.Fail(f + ".name", "'" + rc.name + "' must be letters, digits, '_', '-' or '.'");
    }
    if (!names.insert(rc.name).second) {
      return c.Fail(f + ".name", "condition '" + rc.name + "' appears twice");
    }
    // f_lug = lugs V / (2 pi r_e0): a lug order exists only rolling.
    if (!c.Positive(jc.speed_m_s, f + ".speed_m_s")) return false;
    rc.speed_m_s = jc.speed_m_s;
    if (jc.f_lug_hz && !c.Positive(*jc.f_lug_hz, f + ".f_lug_hz")) return false;
    rc.f_lug_hz = jc.f_lug_hz;
    for (const auto& [name, v] : jc.known.value_or(std::map<std::string, double>{})) {
      const std::string field = f + ".known." + name;
      const auto p = ParseParam(name);
      if (!p) return c.Fail(field, UnknownName("parameter", name, NamesOf<Param>()));
      if (const std::string problem = ParameterValueProblem(*p, v); !problem.empty()) {
        return c.Fail(field, problem);
      }
      rc.known[*p] = v;
    }
    if (jc.orders.empty()) return c.Fail(f + ".orders", "must be a non-empty array");
    std::set<int> orders;
    for (size_t k = 0; k < jc.orders.size(); ++k) {
      const OrderFields& jo = jc.orders[k];
      const std::string fo = f + ".orders[" + std::to_string(k) + "]";
      if (jo.order < 1) return c.Fail(fo + ".order", "must be a positive whole number");
      if (!orders.insert(jo.order).second) {
        return c.Fail(fo + ".order", "order " + std::to_string(jo.order) + " appears twice");
      }
      if (jo.response.empty()) {
        return c.Fail(fo + ".response", "names no channel (expected " +
                                            OneOf(NamesOf<AxleChannel>()) + ")");
      }
      OrderResponse ro;
      ro.order = jo.order;
      for (const auto& [name, phasor] : jo.response) {
        const std::string fc = fo + ".response." + name;
        const auto channel = FromString<AxleChannel>(name);
        if (!channel) return c.Fail(fc, UnknownName("channel", name, NamesOf<AxleChannel>()));
        if (!std::isfinite(phasor.re)) return c.Fail(fc + ".re", "must be a number");
        if (!std::isfinite(phasor.im)) return c.Fail(fc + ".im", "must be a number");
        if (!c.Positive(phasor.sigma, fc + ".sigma")) return false;
        ro.channels[*channel] = {{phasor.re, phasor.im}, phasor.sigma};
      }
      rc.orders.push_back(ro);
    }
    d->conditions.push_back(rc);
  }
  return true;
}

bool CheckLugForces(const LugForcesFields& j, LugForceSpectrum* s, LoadError* error) {
  Checker c(error);
  s->name = j.name;
  if (s->name.empty()) return c.Fail("name", "must not be empty");
  s->description = j.description.value_or("");
  s->lugs_per_revolution = j.lugs_per_revolution;
  if (j.lugs_per_revolution <= 0) return c.Fail("lugs_per_revolution", "must be positive");
  if (j.orders.empty()) return c.Fail("orders", "must be a non-empty array");
  for (size_t k = 0; k < j.orders.size(); ++k) {
    const LugForceOrderFields& o = j.orders[k];
    const std::string f = "orders[" + std::to_string(k) + "]";
    if (o.order < 1) return c.Fail(f + ".order", "must be a positive whole number");
    if (s->orders.count(o.order)) {
      return c.Fail(f + ".order", "order " + std::to_string(o.order) + " appears twice");
    }
    if (o.forces.empty()) {
      return c.Fail(f + ".forces", "names no force (expected " + OneOf(NamesOf<LugForce>()) + ")");
    }
    auto& forces = s->orders[o.order];
    forces.fill(0.0);
    for (const auto& [name, value] : o.forces) {
      const auto force = FromString<LugForce>(name);
      if (!force) return c.Fail(f + ".forces." + name, UnknownName("force", name, NamesOf<LugForce>()));
      if (!std::isfinite(value.real()) || !std::isfinite(value.imag())) {
        return c.Fail(f + ".forces." + name, "must be finite");
      }
      forces[static_cast<int>(*force)] = value;
    }
  }
  return true;
}

}  // namespace

bool ParseLugForces(const std::string& text, const std::string& path, LugForceSpectrum* spectrum,
                    LoadError* error) {
  *spectrum = LugForceSpectrum{};
  return ReadTyped<LugForcesFields>(text, path, kLugForcesFormat, error, [&](const LugForcesFields& j) {
    return CheckLugForces(j, spectrum, error);
  });
}

bool LoadLugForces(const std::string& path, LugForceSpectrum* spectrum, LoadError* error) {
  std::string text;
  return ReadInputFile(path, &text, error) && ParseLugForces(text, path, spectrum, error);
}

bool ParseResponseDataset(const std::string& text, const std::string& path, ResponseDataset* data,
                          LoadError* error) {
  *data = ResponseDataset{};
  data->path = path;
  return ReadTyped<ResponseDatasetFields>(text, path, kResponseFormat, error,
                                         [&](const ResponseDatasetFields& j) {
    return Check(j, data, error);
  });
}

bool LoadResponseDataset(const std::string& path, ResponseDataset* data, LoadError* error) {
  std::string text;
  return ReadInputFile(path, &text, error) && ParseResponseDataset(text, path, data, error);
}

bool SimulateResponses(const RigidRingModel& model, const Parameters& p, int lugs,
                       const std::vector<double>& speeds, int orders,
                       const std::vector<AxleChannel>& channels, const LugForceOrders& forces,
                       double relative_noise, std::mt19937_64* rng, ResponseDataset* data,
                       std::string* why) {
  std::normal_distribution<double> n(0, 1);
  data->lugs_per_revolution = lugs;
  data->conditions.clear();
  for (double v : speeds) {
    char name[32];
    std::snprintf(name, sizeof name, "drum_%g", v);
    ResponseCondition c;
    c.name = name;
    c.speed_m_s = v;
    for (int k = 1; k <= orders; ++k) {
      const auto F = forces(k);
      if (std::all_of(F.begin(), F.end(), [](std::complex<double> f) { return f == 0.0; })) {
        continue;  // no force at this order: nothing measured there
      }
      AxleResponseMatrix H;
      if (!AxleResponse(model, p, v, LugOrderHz(k, lugs, p[Param::r_e0], v), &H, why)) {
        return false;
      }
      OrderResponse o{k, {}};
      std::map<AxleChannel, std::complex<double>> Y;
      double largest = 0;
      for (AxleChannel ch : channels) {
        for (int f = 0; f < kNumLugForces; ++f) Y[ch] += H(static_cast<int>(ch), f) * F[f];
        largest = std::max(largest, std::abs(Y[ch]));
      }
      if (!(largest > 0)) {
        *why = "order " + std::to_string(k) + ": no channel responds to its forces";
        return false;
      }
      for (auto [ch, y] : Y) {
        // A channel the forces leave still (the other plane) gets the noise of
        // a thousandth of the order's largest amplitude: a sigma must be positive.
        const double sigma = relative_noise * std::max(std::abs(y), 1e-3 * largest);
        if (rng) {
          // Two statements: in one call the order of the draws is the compiler's.
          // The imaginary part first, as the shipped examples were drawn.
          const double im = sigma * n(*rng);
          const double re = sigma * n(*rng);
          y += std::complex<double>(re, im);
        }
        o.channels[ch] = {y, sigma};
      }
      c.orders.push_back(o);
    }
    data->conditions.push_back(c);
  }
  return true;
}

std::string LugForcesToJson(const LugForceSpectrum& s) {
  LugForcesFields j;
  j.name = s.name;
  if (!s.description.empty()) j.description = s.description;
  j.lugs_per_revolution = s.lugs_per_revolution;
  for (const auto& [order, forces] : s.orders) {
    LugForceOrderFields o;
    o.order = order;
    for (int f = 0; f < kNumLugForces; ++f) o.forces[ToString(static_cast<LugForce>(f))] = forces[f];
    j.orders.push_back(o);
  }
  return JsonWriter::ToJson(j).dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

std::string ResponseDatasetToJson(const ResponseDataset& d) {
  ResponseDatasetFields j;
  j.name = d.name;
  if (!d.description.empty()) j.description = d.description;
  j.lugs_per_revolution = d.lugs_per_revolution;
  for (const ResponseCondition& rc : d.conditions) {
    ResponseConditionFields jc;
    jc.name = rc.name;
    jc.speed_m_s = rc.speed_m_s;
    jc.f_lug_hz = rc.f_lug_hz;
    if (!rc.known.empty()) {
      jc.known.emplace();
      for (const auto& [p, v] : rc.known) (*jc.known)[ParamName(p)] = v;
    }
    for (const OrderResponse& ro : rc.orders) {
      OrderFields jo;
      jo.order = ro.order;
      for (const auto& [channel, phasor] : ro.channels) {
        jo.response[ToString(channel)] = {phasor.value.real(), phasor.value.imag(), phasor.sigma};
      }
      jc.orders.push_back(jo);
    }
    j.conditions.push_back(jc);
  }
  return JsonWriter::ToJson(j).dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace ringid
