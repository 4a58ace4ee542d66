// The `frf` block of a dataset-format-3 condition (contract §9): frequency
// response functions as a hammer or shaker test measures them, before any
// modal extraction. FrfFields is the block's field list (model/archive.h
// reads, writes and documents it); ReadFrf checks what the list cannot say
// and gives the typed Frf; FieldsOf(Frf) writes it back as it was given, so
// that what ringid writes reads back to the same bytes.
#ifndef RINGID_DATASETS_FRF_H_
#define RINGID_DATASETS_FRF_H_

#include <algorithm>
#include <array>
#include <complex>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "model/archive.h"
#include "model/names.h"

namespace ringid {

struct LoadError;  // datasets/dataset.h

// The body a point is on (contract §9).
enum class FrfBody : int { kBelt = 0, kRim };
template <>
struct EnumNames<FrfBody> {
  static constexpr std::array<const char*, 2> kNames = {"belt", "rim"};
};
// What a motion output measures, per newton: m, m/s or m/s² (rad for a rotation).
enum class FrfQuantity : int { kDisplacement = 0, kVelocity, kAcceleration };
template <>
struct EnumNames<FrfQuantity> {
  static constexpr std::array<const char*, 3> kNames = {"displacement", "velocity",
                                                        "acceleration"};
};

// The fields as the file has them; names the enums cannot hold (a degree of
// freedom, an input's or output's name) stay strings so that the reader can
// answer a typo with the nearest valid name.

// A point and a direction, flat in its input's or output's object: all three
// or none.
struct FrfPointFields {
  std::optional<FrfBody> on;
  std::optional<std::vector<double>> point_m;    // [p_x, p_y, p_z] from the body's centre at rest
  std::optional<std::vector<double>> direction;  // [d_x, d_y, d_z], any non-zero length

  template <class Archive>
  void Serialize(Archive* a) {
    a->VisitIfSet("on", &on);
    a->VisitIfSet("point_m", &point_m);
    a->VisitIfSet("direction", &direction);
  }
};

// One of a point force, §8's contact force, or generalised forces per newton.
struct FrfInputFields {
  std::string name;
  FrfPointFields point;
  std::optional<LugForce> contact;
  std::optional<std::map<std::string, double>> coordinates;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("name", &name);
    point.Serialize(a);
    a->VisitIfSet("contact", &contact);
    a->VisitIfSet("coordinates", &coordinates);
  }
};

// A point motion or a combination of coordinates (with quantity), or one of
// §8's axle channels.
struct FrfOutputFields {
  std::string name;
  FrfPointFields point;
  std::optional<std::map<std::string, double>> coordinates;
  std::optional<FrfQuantity> quantity;
  std::optional<AxleChannel> channel;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("name", &name);
    point.Serialize(a);
    a->VisitIfSet("coordinates", &coordinates);
    a->VisitIfSet("quantity", &quantity);
    a->VisitIfSet("channel", &channel);
  }
};

// H of one output per unit of one input, per frequency line; its noise as
// sigma, or as coherence with averages.
struct FrfFunctionFields {
  std::string output, input;
  std::vector<double> re, im;
  std::optional<std::vector<double>> sigma;
  std::optional<std::vector<double>> coherence;  // gamma^2 per line
  std::optional<int> averages;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("output", &output);
    a->Visit("input", &input);
    a->Visit("re", &re);
    a->Visit("im", &im);
    a->VisitIfSet("sigma", &sigma);
    a->VisitIfSet("coherence", &coherence);
    a->VisitIfSet("averages", &averages);
  }
};

struct FrfFields {
  std::vector<FrfInputFields> inputs;
  std::vector<FrfOutputFields> outputs;
  std::vector<double> frequencies_hz;
  std::vector<FrfFunctionFields> functions;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("inputs", &inputs);
    a->Visit("outputs", &outputs);
    a->Visit("frequencies_hz", &frequencies_hz);
    a->Visit("functions", &functions);
  }
};

// The typed block.

// Coefficients on generalised coordinates: an input's generalised forces per
// newton, or an output's motion per unit of each coordinate.
using DofCombination = std::map<Dof, double>;

// A point and a direction as given; the combination uses the direction
// normalised.
struct FrfPoint {
  FrfBody on = FrfBody::kBelt;
  std::array<double, 3> point_m{};
  std::array<double, 3> direction{};
};

struct FrfInput {
  std::string name;
  std::optional<FrfPoint> point;    // a point force, or
  std::optional<LugForce> contact;  // §8's contact force (its generalised forces need
                                    // r_e0, r_l0, t_0: the fit makes them), or neither:
  // a point's rigid combination (PointCombination), the coordinates as given,
  // or empty for a contact force.
  DofCombination coordinates;
};

struct FrfOutput {
  std::string name;
  std::optional<FrfPoint> point;        // a point motion, or
  std::optional<AxleChannel> channel;   // an axle channel (hub held; N or N m per N), or neither:
  DofCombination coordinates;           // as for FrfInput; empty for a channel
  FrfQuantity quantity = FrfQuantity::kDisplacement;  // of a point or coordinates output
};

// The noise given as coherence gamma^2 per line and the number of averages.
struct FrfCoherence {
  std::vector<double> gamma2;
  int averages = 1;
};

struct FrfFunction {
  int output = 0;  // index into Frf::outputs
  int input = 0;   // index into Frf::inputs
  std::vector<std::complex<double>> h;  // per frequency line
  std::vector<double> sigma;            // per line: the standard error of re and of im each
  std::optional<FrfCoherence> coherence;  // where sigma was given so (written back so)
};

struct Frf {
  std::vector<FrfInput> inputs;
  std::vector<FrfOutput> outputs;
  std::vector<double> frequencies_hz;  // strictly increasing, > 0; shared by every function
  std::vector<FrfFunction> functions;
};

// A line's sigma at `relative` of its |h|, and at least that share of
// kFrfSigmaFloor times its function's largest |h|, `peak`: the floor keeps an
// anti-resonance, where the sensor's noise floor and not the structure sets
// the value, from weighing a hundred times a resonance. The default level,
// where nothing gives the noise (a UFF function without coherence), is 2 %:
// the random error of an H1 estimate with coherence 0.99 and 10 averages
// (sqrt(0.01 / (2 * 10 * 0.99)) = 0.022).
inline constexpr double kDefaultFrfRelativeSigma = 0.02;
inline constexpr double kFrfSigmaFloor = 0.01;
inline double FrfSigma(double relative, std::complex<double> h, double peak) {
  return relative * std::max(std::abs(h), kFrfSigmaFloor * peak);
}

// Bendat & Piersol's random error of a single-input H1 estimate (contract §9):
// |h| sqrt((1 - gamma2) / (2 averages gamma2)).
double CoherenceSigma(std::complex<double> h, double gamma2, int averages);

// Contract §9's rigid point combination, the direction normalised (non-zero):
// on the belt x_b: d_x, y_b: d_y, z_b: d_z, gamma_b: d_z p_y - d_y p_z,
// theta_b: d_z p_x - d_x p_z, psi_b: d_y p_x - d_x p_y; on the rim theta_a:
// d_z p_x - d_x p_z and x_a, y_a, z_a: d (which act only where hub_compliance
// frees the hub). Zero coefficients are left out.
DofCombination PointCombination(const FrfPoint& point);

// Checks `fields`, the frf block of a condition at `speed_m_s`, as contract §9
// asks, and fills `out`. False with `error` (file `path`, field under
// `field`, e.g. "conditions[1].frf.functions[3].im") at the first rule broken.
// Not checked here: a coordinate the model of the run lacks (x_a without
// hub_compliance), which needs the run's effects.
bool ReadFrf(const FrfFields& fields, double speed_m_s, const std::string& path,
             const std::string& field, Frf* out, LoadError* error);

// The fields of `frf` as given: a point as its point and direction, the noise
// as sigma or as coherence and averages.
FrfFields FieldsOf(const Frf& frf);

}  // namespace ringid

#endif  // RINGID_DATASETS_FRF_H_
