// The obstacle block and spec (contract §11): what the field lists cannot say.
#include "datasets/obstacle.h"

#include <cmath>

#include "datasets/dataset.h"
#include "datasets/load_failure.h"
#include "datasets/typed_file.h"
#include "model/names.h"
#include "model/time_response.h"

namespace ringid {
namespace {

using internal::Captured;
using internal::Fail;

// A sample takes at least 4 bytes of a file (a digit, a separator, twice):
// more could not be read back.
constexpr double kMostSamples = kMaxFileBytes / 4.0;

double Finite(double v, const std::string& field) {
  if (!std::isfinite(v)) Fail(field, "must be a finite number");
  return v;
}

// Where a run starts: within kFarthestX of the profile's 0.
double Position(double v, const std::string& field) {
  if (!(std::abs(v) <= kFarthestX)) Fail(field, "must lie within 10000 m of 0");
  return v;
}

// A field the kind needs, or refuses.
double Needed(const std::optional<double>& v, const std::string& field, const char* kind) {
  if (!v) Fail(field, std::string("missing: a ") + kind + " profile needs it (contract §11)");
  return Finite(*v, field);
}
template <class T>
void NotFor(const std::optional<T>& v, const std::string& field, const char* kind) {
  if (v) Fail(field, std::string("not for a ") + kind + " profile (contract §11)");
}

ObstacleProfile ProfileOf(const ObstacleProfileFields& j, const std::string& prefix) {
  ObstacleProfile p;
  p.kind = j.kind;
  const char* kind = ToString(j.kind);
  if (j.kind == ProfileKind::kPoints) {
    for (const auto* v : {&j.height_m, &j.length_m, &j.pitch_m}) {
      NotFor(*v, prefix + (v == &j.height_m ? "height_m" : v == &j.length_m ? "length_m" : "pitch_m"),
             kind);
    }
    if (!j.x_m) Fail(prefix + "x_m", "missing: a points profile needs it (contract §11)");
    if (!j.h_m) Fail(prefix + "h_m", "missing: a points profile needs it (contract §11)");
    p.x_m = *j.x_m;
    p.h_m = *j.h_m;
  } else {
    NotFor(j.x_m, prefix + "x_m", kind);
    NotFor(j.h_m, prefix + "h_m", kind);
    p.height_m = Needed(j.height_m, prefix + "height_m", kind);
    p.length_m = Needed(j.length_m, prefix + "length_m", kind);
    if (j.kind == ProfileKind::kLugs) {
      p.pitch_m = Needed(j.pitch_m, prefix + "pitch_m", kind);
    } else {
      NotFor(j.pitch_m, prefix + "pitch_m", kind);
    }
  }
  p.width_m = j.width_m;
  p.angle_deg = j.angle_deg.value_or(0);
  p.lanes = j.lanes.value_or(p.lanes);
  p.pattern = j.pattern;
  if (!p.width_m) {
    if (j.angle_deg) Fail(prefix + "angle_deg", "only with width_m: the lanes across it carry the angle");
    if (j.lanes) Fail(prefix + "lanes", "only with width_m: the lanes lie across it");
  }
  const std::string why = p.Invalid();
  if (!why.empty()) {
    const size_t colon = why.find(": ");
    Fail(prefix + why.substr(0, colon), why.substr(colon + 2));
  }
  return p;
}

std::vector<double> Sigma(const std::variant<double, std::vector<double>>& s, size_t samples,
                          const std::string& field, bool* one) {
  *one = std::holds_alternative<double>(s);
  std::vector<double> out = *one ? std::vector<double>(samples, std::get<double>(s))
                                 : std::get<std::vector<double>>(s);
  if (out.size() != samples) {
    Fail(field, "has " + std::to_string(out.size()) + " values for " + std::to_string(samples) +
                    " samples: give one number or one per sample");
  }
  for (size_t k = 0; k < out.size(); ++k) {
    if (!(std::isfinite(out[k]) && out[k] > 0)) {
      Fail(*one ? field : field + "[" + std::to_string(k) + "]", "must be a positive number");
    }
  }
  return out;
}

std::vector<double> Times(const ObstacleFields& j, const std::string& prefix, double speed) {
  std::vector<double> t;
  if (j.time_s && (j.sample_rate_hz || j.samples)) {
    Fail(prefix + "time_s", "not with sample_rate_hz and samples: the times are given one way");
  }
  if (j.time_s) {
    t = *j.time_s;
    if (t.empty()) Fail(prefix + "time_s", "must hold at least one time");
    for (size_t k = 0; k < t.size(); ++k) {
      const std::string f = prefix + "time_s[" + std::to_string(k) + "]";
      if (!(std::isfinite(t[k]) && t[k] >= 0)) Fail(f, "must be a number of seconds >= 0");
      if (k > 0 && !(t[k] > t[k - 1])) Fail(f, "must exceed the time before it");
    }
  } else {
    if (!j.sample_rate_hz) {
      Fail(prefix + "time_s", "missing: give time_s [...] or sample_rate_hz with samples");
    }
    if (!j.samples) Fail(prefix + "samples", "missing: sample_rate_hz needs it");
    const double rate = *j.sample_rate_hz;
    if (!(std::isfinite(rate) && rate > 0)) Fail(prefix + "sample_rate_hz", "must be a positive number");
    if (!(*j.samples >= 1 && *j.samples <= kMostSamples)) {
      Fail(prefix + "samples", "must be a whole number from 1 to " +
                                   std::to_string(static_cast<long>(kMostSamples)));
    }
    for (int k = 0; k < *j.samples; ++k) t.push_back(k / rate);
  }
  if (speed * t.back() / kTravelStep > static_cast<double>(kMostSteps)) {
    Fail(prefix + (j.time_s ? "time_s" : "samples"),
         "reaches beyond " + std::to_string(kMostSteps) + " travel steps of 1 mm at this speed");
  }
  return t;
}

void Check(const ObstacleFields& j, double speed, const std::string& block, ObstacleTest* test) {
  const std::string prefix = block.empty() ? "" : block + ".";
  if (!(speed >= kSlowestRoll && speed <= kFastestRoll)) {
    Fail(block, "an obstacle condition rolls: its speed_m_s must lie in [0.001, 200] m/s "
                "(contract §11)");
  }
  test->profile = ProfileOf(j.profile, prefix + "profile.");
  if (j.position_at_t0_m) test->position_at_t0_m = Position(*j.position_at_t0_m, prefix + "position_at_t0_m");
  test->times_s = Times(j, prefix, speed);
  test->sample_rate_hz = j.time_s ? std::nullopt : j.sample_rate_hz;
  if (j.outputs.empty()) Fail(prefix + "outputs", "must name at least one channel");
  for (int o = 0; o < kNumTimeOutputs; ++o) {
    const auto it = j.outputs.find(TimeOutputName(o));
    if (it == j.outputs.end()) continue;
    const std::string f = prefix + "outputs." + it->first;
    ObstacleChannel c;
    c.output = o;
    c.values = it->second.values;
    if (c.values.size() != test->times_s.size()) {
      Fail(f + ".values", "has " + std::to_string(c.values.size()) + " values for " +
                              std::to_string(test->times_s.size()) + " samples");
    }
    for (size_t k = 0; k < c.values.size(); ++k) {
      Finite(c.values[k], f + ".values[" + std::to_string(k) + "]");
    }
    c.sigma = Sigma(it->second.sigma, c.values.size(), f + ".sigma", &c.one_sigma);
    test->channels.push_back(std::move(c));
  }
  for (const auto& [name, channel] : j.outputs) {
    if (!ParseTimeOutput(name)) {
      Fail(prefix + "outputs." + name, "unknown channel (expected " + TimeOutputChoices() + ")");
    }
  }
}

}  // namespace

bool ReadObstacle(const ObstacleFields& fields, double speed_m_s, const std::string& path,
                  const std::string& prefix, ObstacleTest* test, LoadError* error) {
  *test = ObstacleTest{};
  error->file = path;
  return Captured(error, [&] { Check(fields, speed_m_s, prefix, test); });
}

ObstacleProfileFields FieldsOf(const ObstacleProfile& p) {
  ObstacleProfileFields j;
  j.kind = p.kind;
  if (p.kind == ProfileKind::kPoints) {
    j.x_m = p.x_m;
    j.h_m = p.h_m;
  } else {
    j.height_m = p.height_m;
    j.length_m = p.length_m;
    if (p.kind == ProfileKind::kLugs) j.pitch_m = p.pitch_m;
  }
  if (p.width_m) {
    j.width_m = p.width_m;
    j.angle_deg = p.angle_deg;
    j.lanes = p.lanes;
  }
  j.pattern = p.pattern;
  return j;
}

ObstacleFields FieldsOf(const ObstacleTest& t) {
  ObstacleFields j;
  j.profile = FieldsOf(t.profile);
  j.position_at_t0_m = t.position_at_t0_m;
  if (t.sample_rate_hz) {
    j.sample_rate_hz = t.sample_rate_hz;
    j.samples = static_cast<int>(t.times_s.size());
  } else {
    j.time_s = t.times_s;
  }
  for (const ObstacleChannel& c : t.channels) {
    ObstacleChannelFields f;
    f.values = c.values;
    if (c.one_sigma) {
      f.sigma = c.sigma.front();
    } else {
      f.sigma = c.sigma;
    }
    j.outputs[TimeOutputName(c.output)] = std::move(f);
  }
  return j;
}

namespace {

bool CheckSpec(const ObstacleSpecFields& j, ObstacleSpec* spec, LoadError* error) {
  return Captured(error, [&] {
    if (j.speeds_m_s.empty() || j.speeds_m_s.size() > kMostObstacleSpeeds) {
      Fail("speeds_m_s", "must name 1 to " + std::to_string(kMostObstacleSpeeds) + " speeds");
    }
    for (size_t i = 0; i < j.speeds_m_s.size(); ++i) {
      const double v = j.speeds_m_s[i];
      if (!(v >= kSlowestRoll && v <= kFastestRoll)) {
        Fail("speeds_m_s[" + std::to_string(i) + "]",
             "must be a speed of 0.001 to 200 m/s: the tire rolls over the obstacle "
             "(contract §11)");
      }
      for (size_t k = 0; k < i; ++k) {
        if (j.speeds_m_s[k] == v) Fail("speeds_m_s[" + std::to_string(i) + "]", "appears twice");
      }
    }
    spec->speeds_m_s = j.speeds_m_s;
    spec->profile = ProfileOf(j.profile, "profile.");
    spec->position_at_t0_m = Position(j.position_at_t0_m, "position_at_t0_m");
    if (!(std::isfinite(j.sample_rate_hz) && j.sample_rate_hz > 0)) {
      Fail("sample_rate_hz", "must be a positive number of Hz");
    }
    spec->sample_rate_hz = j.sample_rate_hz;
    const double n = std::round(j.duration_s * j.sample_rate_hz);
    if (!(std::isfinite(j.duration_s) && j.duration_s > 0 && n >= 1 && n <= kMostSamples)) {
      Fail("duration_s", "must be positive and give 1 to " +
                             std::to_string(static_cast<long>(kMostSamples)) +
                             " samples at sample_rate_hz");
    }
    spec->samples = static_cast<int>(n);
    const double last = (spec->samples - 1) / spec->sample_rate_hz;
    for (double v : spec->speeds_m_s) {
      if (v * last / kTravelStep > static_cast<double>(kMostSteps)) {
        Fail("duration_s", "reaches beyond " + std::to_string(kMostSteps) +
                               " travel steps of 1 mm at the fastest speed");
      }
    }
    if (j.outputs.empty()) Fail("outputs", "must name at least one channel");
    for (size_t i = 0; i < j.outputs.size(); ++i) {
      const auto o = ParseTimeOutput(j.outputs[i]);
      const std::string f = "outputs[" + std::to_string(i) + "]";
      if (!o) Fail(f, "unknown channel '" + j.outputs[i] + "' (expected " + TimeOutputChoices() + ")");
      for (int before : spec->outputs) {
        if (before == *o) Fail(f, "'" + j.outputs[i] + "' appears twice");
      }
      spec->outputs.push_back(*o);
    }
    // Each value takes at least 8 bytes of the dataset (digits, a separator).
    if (8.0 * spec->samples * spec->outputs.size() * spec->speeds_m_s.size() > kMaxFileBytes) {
      Fail("duration_s", "lays out more samples over its speeds and outputs than a dataset of at "
                         "most " + std::to_string(kMaxFileBytes) + " bytes holds");
    }
    if (j.noise) {
      if (!(*j.noise >= 0 && *j.noise <= 1)) {
        Fail("noise", "must be a number from 0 to 1 (sigma relative to the channel's "
                      "peak-to-peak; 0: no noise)");
      }
      spec->noise = *j.noise;
    }
  });
}

}  // namespace

bool ParseObstacleSpec(const std::string& text, const std::string& path, ObstacleSpec* spec,
                       LoadError* error) {
  *spec = ObstacleSpec{};
  spec->path = path;
  return internal::ReadTyped<ObstacleSpecFields>(
      text, path, kObstacleSpecFormat, error,
      [&](const ObstacleSpecFields& j) { return CheckSpec(j, spec, error); });
}

bool ParseLugProfile(const std::string& text, const std::string& path, ObstacleProfile* lugs,
                     LoadError* error) {
  return internal::ReadTyped<LugProfileFields>(
      text, path, kLugProfileFormat, error, [&](const LugProfileFields& j) {
        return Captured(error, [&] {
          if (j.profile.kind != ProfileKind::kLugs) {
            Fail("profile.kind", "must be lugs: a tread's lugs, rolled out (contract §11)");
          }
          *lugs = ProfileOf(j.profile, "profile.");
        });
      });
}

bool LoadLugProfile(const std::string& path, ObstacleProfile* lugs, LoadError* error) {
  std::string text;
  return ReadInputFile(path, &text, error) && ParseLugProfile(text, path, lugs, error);
}

bool LoadObstacleSpec(const std::string& path, ObstacleSpec* spec, LoadError* error) {
  std::string text;
  return ReadInputFile(path, &text, error) && ParseObstacleSpec(text, path, spec, error);
}

}  // namespace ringid
