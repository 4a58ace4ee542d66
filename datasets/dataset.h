// The modal dataset of docs/conventions.md §3 and its strict loader.
#ifndef RINGID_DATASETS_DATASET_H_
#define RINGID_DATASETS_DATASET_H_

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "datasets/frf.h"
#include "datasets/obstacle.h"
#include "model/names.h"
#include "model/parameters.h"

namespace ringid {

struct MeasuredMode {
  ModeLabel label;
  double frequency_hz = 0;
  std::optional<double> frequency_sigma_hz;
  std::optional<double> damping_ratio;
  std::optional<double> damping_sigma;
  std::vector<std::pair<Dof, double>> shape;  // empty: no shape measured
  std::optional<double> shape_sigma;
  int condition = 0;  // index into Dataset::conditions
};

// A static stiffness measured in a standing condition (contract §10): the
// force at the contact per unit road displacement in `direction` (N/m).
struct MeasuredStatic {
  StaticDirection direction = StaticDirection::kVertical;
  double value = 0;
  std::optional<double> sigma;  // kDefaultStaticRelativeSigma of value where absent
  int condition = 0;            // index into Dataset::conditions
};
// Contract §10: without `sigma`, 2 % of the value.
inline constexpr double kDefaultStaticRelativeSigma = 0.02;

// One test condition of docs/conventions.md §7: a speed and the values of the
// per-condition parameters that are known or seeded there.
struct Condition {
  std::string name = "standing";
  double speed_m_s = 0;
  std::map<Param, double> known;    // per_condition parameters only
  std::map<Param, double> initial;  // per_condition parameters only
  // Format 3: the condition's frequency response functions (contract §9),
  // read, written and fitted.
  std::optional<Frf> frf;
  // Format 3: the axle's response to rolling over an obstacle (contract
  // §11), read and written.
  std::optional<ObstacleTest> obstacle;
};

// A prior of docs/conventions.md §7, in the units of its parameter.
enum class PriorDistribution { kNormal, kLognormal };
template <>
struct EnumNames<PriorDistribution> {
  static constexpr std::array<const char*, 2> kNames = {"normal", "lognormal"};
};
struct Prior {
  PriorDistribution distribution = PriorDistribution::kNormal;
  double center = 0;  // normal: mean; lognormal: median
  double spread = 0;  // normal: sigma; lognormal: factor_95 (> 1)
};

struct Dataset {
  std::string path;  // where it was loaded from, for messages
  std::string name;
  std::string description;
  std::map<Param, double> known;
  std::map<Param, double> initial;
  std::map<Param, Param> ties;  // parameter -> the one whose value it shares
  int format = 1;               // 1, 2 or 3 (docs/conventions.md §3, §7, §10)
  std::map<Param, Prior> priors;
  std::vector<Param> per_condition;  // catalogue order; one value per condition
  // At least one; a format-1 file has one, "standing" at speed 0.
  std::vector<Condition> conditions = {Condition{}};
  // Every measured mode of every condition, each naming its condition.
  std::vector<MeasuredMode> modes;
  // Every static stiffness of every condition (format 3), each naming its
  // condition.
  std::vector<MeasuredStatic> statics;

  bool IsPerCondition(Param p) const;
  // Whether the conditions are named in reports (formats 2 and 3).
  bool NamesConditions() const { return format >= 2; }
};

// The "format" of each kind of file (docs/conventions.md §3, §7).
inline constexpr char kDatasetFormat1[] = "ringid-modal-dataset/1";
inline constexpr char kDatasetFormat2[] = "ringid-modal-dataset/2";
inline constexpr char kDatasetFormat3[] = "ringid-dataset/3";
inline constexpr char kParameterSetFormat[] = "ringid-parameters/1";

// Limits the loader enforces (README "Limits").
// At most one measured mode per mode label of docs/conventions.md §1, one
// shape component per degree of freedom, one static stiffness per direction.
inline constexpr int kMaxModes = 7;
inline constexpr int kMaxJsonDepth = 16;
inline constexpr long kMaxFileBytes = 4 << 20;

// Input checked against physics before any solve (docs/conventions.md §3).
// The frequencies a rigid-ring mode can have: the belt's rigid-body modes of
// a tire, from a truck's to a bicycle's, lie between a few Hz and a few
// hundred (paper Table 4: 17-98 Hz); a value outside is a typo or not a
// rigid-ring mode (a bending mode of the belt, a hub resonance, Hz for rad/s).
inline constexpr double kMinModeFrequencyHz = 1;
inline constexpr double kMaxModeFrequencyHz = 1000;
// No parameter of the catalogue, in SI units, comes near this magnitude
// (stiffnesses are 1e4-1e7, docs/reference.md); beyond it a value is absurd.
inline constexpr double kMaxParameterMagnitude = 1e12;
// A measured damping ratio is an underdamped mode's, inside the open interval
// (kMinDampingRatio, kMaxDampingRatio) = (0, 1): the JSON loader, the UFF
// import and the synthetic generator all hold to it (a plausibility rule's
// bound on a sidewall damper is another fact, model/plausibility.cc).
inline constexpr double kMinDampingRatio = 0;
inline constexpr double kMaxDampingRatio = 1;

// Why `v` cannot be a value of `p` (its sign domain, kMaxParameterMagnitude),
// as "must be positive"; empty when it can.
std::string ParameterValueProblem(Param p, double v);
// Why `hz` cannot be a rigid-ring mode's frequency; empty when it can.
std::string ModeFrequencyProblem(double hz);
// Why `zeta` cannot be a measured damping ratio ("must lie in (0, 1)"); empty
// when it can.
std::string DampingRatioProblem(double zeta);
// A condition name (docs/conventions.md §7): letters, digits, '_', '-', '.'.
bool ValidConditionName(const std::string& name);

// What went wrong, as one line: "FILE: FIELD: MESSAGE".
struct LoadError {
  std::string file;
  std::string field;  // JSON path, e.g. "modes[2].frequency_hz"; may be empty
  std::string message;
  std::string OneLine() const;
};

// Reads a whole input file (at most `max_bytes`). False with `error` set.
bool ReadInputFile(const std::string& path, std::string* text, LoadError* error,
                   long max_bytes = kMaxFileBytes);
// Parses an input file's text as JSON, refusing duplicate keys and nesting
// deeper than kMaxJsonDepth; a syntax error names where it is.
bool ParseJsonInput(const std::string& text, nlohmann::ordered_json* out, LoadError* error);
// The archive's "FIELD: MESSAGE" (model/archive.h) as error's field and message.
void SetArchiveError(const std::string& archive_error, LoadError* error);

// The dataset's starting point in `condition`: shared known and initial
// values, that condition's own, ties applied.
Parameters InitialParameters(const Dataset& dataset, int condition = 0);

// Holds each of `fixed` at its initial value: moved from initial to known
// (each condition's own for a per-condition parameter), its prior dropped.
// False, with why naming it, for a parameter the dataset does not leave free.
bool FixParameters(const std::vector<Param>& fixed, Dataset* dataset, std::string* why);

// Loads and checks a dataset. On failure returns false and fills `error`;
// `dataset` is then unspecified.
bool LoadDataset(const std::string& path, Dataset* dataset, LoadError* error);
// The same from text in memory; `path` only names it in messages.
bool ParseDataset(const std::string& text, const std::string& path,
                  Dataset* dataset, LoadError* error);

// The values of a parameter set that the data left undetermined, each with
// why in words: classed no or practically_no, or a class that holds only
// given a known value ("given sigma_cx = 0.1 m (known): the data measure
// K_cx/sigma_cx"), as an identify report or --save_parameters says.
using Undetermined = std::map<Param, std::string>;

// Reads a parameter set (ringid-parameters/1, docs/conventions.md §3): each
// value through ParameterValue's field list (datasets/parameter_files.h), or
// a bare number. An identify report has the same "parameters" object and
// reads back as one. With `undetermined`, the values whose class
// ("no" or "practically_no") or condition says the data left them
// undetermined.
bool LoadParameterSet(const std::string& path, Parameters* p, LoadError* error,
                      Undetermined* undetermined = nullptr);

// Writes the set parameters of `p` as a parameter set (ringid-parameters/1,
// each {"value": V}), which LoadParameterSet reads back; effect parameters at
// their baseline 0 (the default) are left out.
std::string ParameterSetToJson(const Parameters& p, const std::string& name,
                               const std::string& description);

// Writes a dataset back to the JSON form of docs/conventions.md §3
// (datasets/dataset_writer.cc, as ParameterSetToJson).
std::string DatasetToJson(const Dataset& dataset);

}  // namespace ringid

#endif  // RINGID_DATASETS_DATASET_H_
