// The response dataset of contract §8: complex amplitudes of the axle's
// channels at the lug orders of a rolling tire, per drum condition. One field
// list (ResponseDatasetFields) reads, writes and documents it (docs/inputs.md);
// LoadResponseDataset adds the rules it cannot say.
#ifndef RINGID_DATASETS_RESPONSE_DATASET_H_
#define RINGID_DATASETS_RESPONSE_DATASET_H_

#include <array>
#include <complex>
#include <functional>
#include <random>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "datasets/dataset.h"
#include "model/archive.h"
#include "model/names.h"
#include "model/rigid_ring_model.h"

namespace ringid {

inline constexpr char kResponseFormat[] = "ringid-lug-response/1";

// The fields as the file has them (names as strings, for "did you mean").
struct PhasorFields {
  double re = 0, im = 0;
  double sigma = 0;  // standard error of re and of im each

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("re", &re);
    a->Visit("im", &im);
    a->Visit("sigma", &sigma);
  }
};

struct OrderFields {
  int order = 1;
  std::map<std::string, PhasorFields> response;  // channel -> phasor

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("order", &order);
    a->Visit("response", &response);
  }
};

struct ResponseConditionFields {
  std::string name;
  double speed_m_s = 0;
  std::optional<double> f_lug_hz;  // measured by order tracking; wins over the model's
  std::optional<std::map<std::string, double>> known;  // per-condition parameters (§7)
  std::vector<OrderFields> orders;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("name", &name);
    a->Visit("speed_m_s", &speed_m_s);
    a->VisitIfSet("f_lug_hz", &f_lug_hz);
    a->VisitIfSet("known", &known);
    a->Visit("orders", &orders);
  }
};

struct ResponseDatasetFields {
  std::string format = kResponseFormat;
  std::string name;
  std::optional<std::string> description;
  int lugs_per_revolution = 0;
  std::vector<ResponseConditionFields> conditions;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Derived("format", std::string(kResponseFormat));
    a->Visit("name", &name);
    a->VisitIfSet("description", &description);
    a->Visit("lugs_per_revolution", &lugs_per_revolution);
    a->Visit("conditions", &conditions);
  }
};

inline constexpr char kLugForcesFormat[] = "ringid-lug-forces/1";

// The lug forces a simulation puts in (`simulate --lug_forces`): per order,
// the complex amplitude of F_x, F_z and F_y (N; a force left out is 0).
struct LugForceOrderFields {
  int order = 1;
  std::map<std::string, std::complex<double>> forces;  // force -> {re, im}

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("order", &order);
    a->Visit("forces", &forces);
  }
};

struct LugForcesFields {
  std::string name;
  std::optional<std::string> description;
  int lugs_per_revolution = 0;
  std::vector<LugForceOrderFields> orders;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Derived("format", std::string(kLugForcesFormat));
    a->Visit("name", &name);
    a->VisitIfSet("description", &description);
    a->Visit("lugs_per_revolution", &lugs_per_revolution);
    a->Visit("orders", &orders);
  }
};

struct LugForceSpectrum {
  std::string name;
  std::string description;
  int lugs_per_revolution = 0;
  std::map<int, std::array<std::complex<double>, kNumLugForces>> orders;  // by order
};

// Reads and checks a lug-force file: false with `error` (file, field, message).
bool LoadLugForces(const std::string& path, LugForceSpectrum* spectrum, LoadError* error);
bool ParseLugForces(const std::string& text, const std::string& path, LugForceSpectrum* spectrum,
                    LoadError* error);
// The file text of `spectrum`, every force of every order (LoadLugForces
// reads it back).
std::string LugForcesToJson(const LugForceSpectrum& spectrum);

// A measured channel at one order.
struct Phasor {
  std::complex<double> value;
  double sigma = 0;
};

struct OrderResponse {
  int order = 1;
  std::map<AxleChannel, Phasor> channels;
};

struct ResponseCondition {
  std::string name;
  double speed_m_s = 0;
  std::optional<double> f_lug_hz;
  std::map<Param, double> known;
  std::vector<OrderResponse> orders;
};

struct ResponseDataset {
  std::string path;  // for messages
  std::string name;
  std::string description;
  int lugs_per_revolution = 0;
  std::vector<ResponseCondition> conditions;
};

// What a drum test would measure of known lug forces: at each speed (a
// condition "drum_V"), the orders 1 to `orders` that have a force, of `lugs` lug impacts per turn,
// on each of `channels`, the model's response to forces(order) (F_x, F_z,
// F_y), with sigma `relative_noise` of each amplitude on re and on im (of a
// thousandth of the order's largest where a channel is still) and, with
// `rng`, that noise added. False with why where the model cannot respond or
// no channel does.
using LugForceOrders = std::function<std::array<std::complex<double>, kNumLugForces>(int order)>;
bool SimulateResponses(const RigidRingModel& model, const Parameters& p, int lugs,
                       const std::vector<double>& speeds, int orders,
                       const std::vector<AxleChannel>& channels, const LugForceOrders& forces,
                       double relative_noise, std::mt19937_64* rng, ResponseDataset* data,
                       std::string* why);

// Reads and checks a response dataset: false with `error` (file, field,
// message) and `data` unspecified.
bool LoadResponseDataset(const std::string& path, ResponseDataset* data, LoadError* error);
bool ParseResponseDataset(const std::string& text, const std::string& path, ResponseDataset* data,
                          LoadError* error);
// The file text of `data` (LoadResponseDataset reads it back).
std::string ResponseDatasetToJson(const ResponseDataset& data);

}  // namespace ringid

#endif  // RINGID_DATASETS_RESPONSE_DATASET_H_
