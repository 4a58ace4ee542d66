// The modal dataset of docs/conventions.md §3 and its strict loader.
#ifndef RINGID_DATASETS_DATASET_H_
#define RINGID_DATASETS_DATASET_H_

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

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
};

struct Dataset {
  std::string path;  // where it was loaded from, for messages
  std::string name;
  std::string description;
  std::map<Param, double> known;
  std::map<Param, double> initial;
  std::map<Param, Param> ties;  // parameter -> the one whose value it shares
  std::vector<MeasuredMode> modes;
};

// Limits the loader enforces (README "Limits").
// At most one measured mode per mode label of docs/conventions.md §1, one
// shape component per degree of freedom.
inline constexpr int kMaxModes = 7;
inline constexpr int kMaxJsonDepth = 16;
inline constexpr long kMaxFileBytes = 4 << 20;

// What went wrong, as one line: "FILE: FIELD: MESSAGE".
struct LoadError {
  std::string file;
  std::string field;  // JSON path, e.g. "modes[2].frequency_hz"; may be empty
  std::string message;
  std::string OneLine() const;
};

// Reads a whole input file (at most kMaxFileBytes). False with `error` set.
bool ReadInputFile(const std::string& path, std::string* text, LoadError* error);

// The dataset's starting point: known values, initial values, ties applied.
Parameters InitialParameters(const Dataset& dataset);

// Loads and checks a dataset. On failure returns false and fills `error`;
// `dataset` is then unspecified.
bool LoadDataset(const std::string& path, Dataset* dataset, LoadError* error);
// The same from text in memory; `path` only names it in messages.
bool ParseDataset(const std::string& text, const std::string& path,
                  Dataset* dataset, LoadError* error);

// Reads a parameter set: {"format": "ringid-parameters/1", "parameters":
// {NAME: {"value": V, "std": S}}}. An identify report has the same
// "parameters" object and reads back as one.
bool LoadParameterSet(const std::string& path, Parameters* p, LoadError* error);

// Writes a dataset back to the JSON form of docs/conventions.md §3.
std::string DatasetToJson(const Dataset& dataset);

}  // namespace ringid

#endif  // RINGID_DATASETS_DATASET_H_
