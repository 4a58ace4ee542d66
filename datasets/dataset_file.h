// The modal dataset file as one field list (docs/conventions.md §3, §7): the
// archive (model/archive.h) reads it strictly (types, unknown and missing
// keys), writes it, and documents it (`ringid inputs`); what the
// field list cannot say (names, ranges, rules between fields) is the
// loader's, datasets/dataset.cc. Names stay strings here so that the loader
// can answer a typo with the nearest valid name.
#ifndef RINGID_DATASETS_DATASET_FILE_H_
#define RINGID_DATASETS_DATASET_FILE_H_

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "datasets/dataset.h"
#include "model/archive.h"

namespace ringid {

// Parameter values by name, as the file spells them.
using NamedValues = std::map<std::string, double>;

struct ModeFields {
  std::string label;
  std::optional<std::string> plane;  // implied by the label; checked when given
  double frequency_hz = 0;
  std::optional<double> frequency_sigma_hz;
  std::optional<double> damping_ratio;
  std::optional<double> damping_sigma;
  std::optional<std::map<std::string, double>> shape;  // degree of freedom -> component
  std::optional<double> shape_sigma;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("label", &label);
    a->VisitIfSet("plane", &plane);
    a->Visit("frequency_hz", &frequency_hz);
    a->VisitIfSet("frequency_sigma_hz", &frequency_sigma_hz);
    a->VisitIfSet("damping_ratio", &damping_ratio);
    a->VisitIfSet("damping_sigma", &damping_sigma);
    a->VisitIfSet("shape", &shape);
    a->VisitIfSet("shape_sigma", &shape_sigma);
  }
};

// A prior: normal (mean, sigma) or lognormal (median, factor_95).
struct PriorFields {
  std::string distribution;
  std::optional<double> mean, sigma, median, factor_95;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("distribution", &distribution);
    a->VisitIfSet("mean", &mean);
    a->VisitIfSet("sigma", &sigma);
    a->VisitIfSet("median", &median);
    a->VisitIfSet("factor_95", &factor_95);
  }
};

// A static stiffness (contract §10).
struct StaticFields {
  StaticDirection kind = StaticDirection::kVertical;
  double value = 0;
  std::optional<double> sigma;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("kind", &kind);
    a->Visit("value", &value);
    a->VisitIfSet("sigma", &sigma);
  }
};

// A condition: format 2 requires its modes (the loader says so); format 3
// holds any of modes, frf and static, at least one measurement in all.
struct ConditionFields {
  std::string name;
  std::optional<double> speed_m_s;  // 0 when absent
  std::optional<NamedValues> known, initial;
  std::optional<std::vector<ModeFields>> modes;
  std::optional<std::vector<StaticFields>> statics;  // "static", format 3
  std::optional<FrfFields> frf;                      // format 3 (contract §9)
  std::optional<ObstacleFields> obstacle;            // format 3 (contract §11)

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("name", &name);
    a->VisitIfSet("speed_m_s", &speed_m_s);
    a->VisitIfSet("known", &known);
    a->VisitIfSet("initial", &initial);
    a->VisitIfSet("modes", &modes);
    a->VisitIfSet("frf", &frf);
    a->VisitIfSet("static", &statics);
    a->VisitIfSet("obstacle", &obstacle);
  }
};

struct DatasetFields {
  std::string format = kDatasetFormat1;  // read first: it decides the fields after
  std::string name;
  std::optional<std::string> description;
  std::optional<NamedValues> known, initial;
  std::optional<std::map<std::string, std::string>> ties;
  std::vector<ModeFields> modes;  // format 1
  std::optional<std::map<std::string, PriorFields>> priors;  // format 2 from here
  std::optional<std::vector<std::string>> per_condition;
  std::vector<ConditionFields> conditions;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("format", &format);
    a->Visit("name", &name);
    a->VisitIfSet("description", &description);
    a->VisitIfSet("known", &known);
    a->VisitIfSet("initial", &initial);
    a->VisitIfSet("ties", &ties);
    if (format != kDatasetFormat2 && format != kDatasetFormat3) {
      a->Visit("modes", &modes);
      return;
    }
    a->VisitIfSet("priors", &priors);
    a->VisitIfSet("per_condition", &per_condition);
    a->Visit("conditions", &conditions);
  }
};

// The fields of `d` as written (format 1 where it can hold the dataset).
DatasetFields FieldsOf(const Dataset& d);

}  // namespace ringid

#endif  // RINGID_DATASETS_DATASET_FILE_H_
