// The files of parameter values, each one field list through the archive
// (model/archive.h): the parameter set (ringid-parameters/1, docs/
// conventions.md §3) and the truth file of a simulation (ringid-truth/1, §5).
#ifndef RINGID_DATASETS_PARAMETER_FILES_H_
#define RINGID_DATASETS_PARAMETER_FILES_H_

#include <map>
#include <optional>
#include <string>

#include "datasets/dataset.h"
#include "model/archive.h"
#include "model/rigid_ring_model.h"

namespace ringid {

// One value, and what identify said of it where it wrote the file.
struct ParameterValue {
  double value = 0;
  std::optional<double> std;
  std::optional<std::string> identifiable;  // identify's class: yes, practically_no or no
  std::optional<std::string> condition;     // the value it holds only given

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("value", &value);
    a->VisitIfSet("std", &std);
    a->VisitIfSet("identifiable", &identifiable);
    a->VisitIfSet("condition", &condition);
  }
};

struct ParameterSet {
  std::string name;
  std::string description;
  std::map<Param, ParameterValue> parameters;  // catalogue order

  template <class Archive>
  void Serialize(Archive* a) {
    a->Derived("format", std::string(kParameterSetFormat));
    a->Visit("name", &name);
    a->Visit("description", &description);
    a->Visit("parameters", &parameters);
  }
};

// The one writer of ringid-parameters/1 (LoadParameterSet reads it, and the
// looser files docs/conventions.md §3 allows).
std::string ParameterSetText(const ParameterSet& set);

inline constexpr char kTruthFormat[] = "ringid-truth/1";

// What a simulation was made from (docs/conventions.md §5).
struct Truth {
  std::string dataset;  // the dataset file simulated
  std::string effect;   // the truth model's effects, comma-separated, or "none"
  // Every value the simulation used: NAME, or NAME@CONDITION for the value
  // of a per-condition parameter in one condition.
  std::map<std::string, ParameterValue> parameters;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Derived("format", std::string(kTruthFormat));
    a->Visit("dataset", &dataset);
    a->Visit("effect", &effect);
    a->Visit("parameters", &parameters);
  }
  // What the field list cannot say: known effect names, parameter names and
  // values within their domains. False with `error`'s field and message.
  bool Validate(LoadError* error) const;
};

// The truth of simulating `d` with `truth` under `model`.
Truth MakeTruth(const RigidRingModel& model, const Parameters& truth, const Dataset& d,
                const std::string& dataset_file);
std::string TruthText(const Truth& truth);
// Reads and checks a truth file; false with `error` (file, field, message).
bool LoadTruth(const std::string& path, Truth* truth, LoadError* error);

}  // namespace ringid

#endif  // RINGID_DATASETS_PARAMETER_FILES_H_
