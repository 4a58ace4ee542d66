// Rolling over an obstacle in files (contract §11): the `obstacle` block of a
// format-3 condition (a profile, the samples' times and the axle's channels
// measured over them) and the `ringid-obstacle-spec/1` spec of `simulate
// --obstacle`. The physics is model/obstacle.h and model/time_response.h.
#ifndef RINGID_DATASETS_OBSTACLE_H_
#define RINGID_DATASETS_OBSTACLE_H_

#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "model/archive.h"
#include "model/obstacle.h"
#include "model/time_response.h"

namespace ringid {

struct LoadError;  // datasets/dataset.h

inline constexpr char kObstacleSpecFormat[] = "ringid-obstacle-spec/1";

// A profile as a file gives it: the fields of its kind, the lanes' fields
// where any.
struct ObstacleProfileFields {
  ProfileKind kind = ProfileKind::kCleat;
  std::optional<double> height_m, length_m, pitch_m;
  std::optional<std::vector<double>> x_m, h_m;
  std::optional<double> width_m, angle_deg;
  std::optional<int> lanes;
  std::optional<LanePattern> pattern;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("kind", &kind);
    a->VisitIfSet("height_m", &height_m);
    a->VisitIfSet("length_m", &length_m);
    a->VisitIfSet("pitch_m", &pitch_m);
    a->VisitIfSet("x_m", &x_m);
    a->VisitIfSet("h_m", &h_m);
    a->VisitIfSet("width_m", &width_m);
    a->VisitIfSet("angle_deg", &angle_deg);
    a->VisitIfSet("lanes", &lanes);
    a->VisitIfSet("pattern", &pattern);
  }
};

// One channel over the samples: its values and sigma, one for all or one per
// sample.
struct ObstacleChannelFields {
  std::vector<double> values;
  std::variant<double, std::vector<double>> sigma;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("values", &values);
    a->Visit("sigma", &sigma);
  }
};

// The block in a condition: the times as time_s or as sample_rate_hz with
// samples (t_k = k / rate); without position_at_t0_m, a fit fits it.
struct ObstacleFields {
  ObstacleProfileFields profile;
  std::optional<double> position_at_t0_m;
  std::optional<std::vector<double>> time_s;
  std::optional<double> sample_rate_hz;
  std::optional<int> samples;
  std::map<std::string, ObstacleChannelFields> outputs;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("profile", &profile);
    a->VisitIfSet("position_at_t0_m", &position_at_t0_m);
    a->VisitIfSet("time_s", &time_s);
    a->VisitIfSet("sample_rate_hz", &sample_rate_hz);
    a->VisitIfSet("samples", &samples);
    a->Visit("outputs", &outputs);
  }
};

// The block, checked.
struct ObstacleChannel {
  int output = 0;  // TimeOutputName's index (model/time_response.h)
  std::vector<double> values;
  std::vector<double> sigma;  // per sample
  bool one_sigma = false;     // given as one number (written back so)
};
struct ObstacleTest {
  ObstacleProfile profile;
  std::optional<double> position_at_t0_m;
  std::vector<double> times_s;
  std::optional<double> sample_rate_hz;  // the times were given so (written back so)
  std::vector<ObstacleChannel> channels;  // in TimeOutputName's order
};

// Checks `fields` of a condition at `speed_m_s` against §11: the profile, the
// times (increasing, >= 0, at most kMostSteps of travel steps), each output a
// channel the model has with a value and a positive sigma per sample. False
// with `error` naming `prefix`'s field.
bool ReadObstacle(const ObstacleFields& fields, double speed_m_s, const std::string& path,
                  const std::string& prefix, ObstacleTest* test, LoadError* error);
ObstacleFields FieldsOf(const ObstacleTest& test);
ObstacleProfileFields FieldsOf(const ObstacleProfile& profile);

// The spec (§11): the speeds, the profile, where the contact centre starts,
// the sampling, the channels and their noise.
struct ObstacleSpecFields {
  std::optional<std::string> description;
  std::vector<double> speeds_m_s;
  ObstacleProfileFields profile;
  double position_at_t0_m = 0;
  double sample_rate_hz = 0;
  double duration_s = 0;
  std::vector<std::string> outputs;
  std::optional<double> noise;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Derived("format", std::string(kObstacleSpecFormat));
    a->VisitIfSet("description", &description);
    a->Visit("speeds_m_s", &speeds_m_s);
    a->Visit("profile", &profile);
    a->Visit("position_at_t0_m", &position_at_t0_m);
    a->Visit("sample_rate_hz", &sample_rate_hz);
    a->Visit("duration_s", &duration_s);
    a->Visit("outputs", &outputs);
    a->VisitIfSet("noise", &noise);
  }
};

// A lugged tread for `predict --lug_profile` (ringid-lug-profile/1): a
// `lugs` profile of §11.
inline constexpr char kLugProfileFormat[] = "ringid-lug-profile/1";
struct LugProfileFields {
  std::optional<std::string> description;
  ObstacleProfileFields profile;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Derived("format", std::string(kLugProfileFormat));
    a->VisitIfSet("description", &description);
    a->Visit("profile", &profile);
  }
};
// Reads and checks one: the profile's rules, and its kind lugs. False with
// `error` naming the field.
bool LoadLugProfile(const std::string& path, ObstacleProfile* lugs, LoadError* error);
bool ParseLugProfile(const std::string& text, const std::string& path, ObstacleProfile* lugs,
                     LoadError* error);

// Contract §11: sigma = this times the peak-to-peak of the channel's noise-free
// series in its condition, where the spec gives no noise.
inline constexpr double kDefaultObstacleNoise = 0.01;
inline constexpr size_t kMostObstacleSpeeds = 100;

struct ObstacleSpec {
  std::string path;  // for messages
  std::vector<double> speeds_m_s;
  ObstacleProfile profile;
  double position_at_t0_m = 0;
  double sample_rate_hz = 0;
  int samples = 0;  // round(duration_s * sample_rate_hz)
  std::vector<int> outputs;
  double noise = kDefaultObstacleNoise;
};

// Reads and checks a spec: every rule of the obstacle block at each speed
// (ReadObstacle), errors naming the spec's own field. False with `error`.
bool LoadObstacleSpec(const std::string& path, ObstacleSpec* spec, LoadError* error);
bool ParseObstacleSpec(const std::string& text, const std::string& path, ObstacleSpec* spec,
                       LoadError* error);

}  // namespace ringid

#endif  // RINGID_DATASETS_OBSTACLE_H_
