// A test lab's UFF modes (dataset 55) as a ringid dataset (docs/uff.md): a
// map (ringid-uff-map/1) says which node and direction is which degree of
// freedom, with sign, and which mode is which label where the user knows it;
// the model labels the others by their shapes (contract §2 pairing).
#ifndef RINGID_DATASETS_UFF_DATASET_H_
#define RINGID_DATASETS_UFF_DATASET_H_

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "datasets/dataset.h"
#include "datasets/measurement_options.h"
#include "datasets/uff.h"
#include "model/archive.h"
#include "model/parameters.h"

namespace ringid {

inline constexpr const char* kUffMapFormat = "ringid-uff-map/1";

// One measured channel: a node's direction as a model degree of freedom.
struct UffChannelFields {
  int node = 0;
  int direction = 0;  // UFF: 1..3 x, y, z translation, 4..6 rotation about them
  std::string dof;    // x_b, z_b, theta_b, ...
  std::optional<double> sign;  // +1 (default) or -1: the model's positive direction against the node's
  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("node", &node);
    a->Visit("direction", &direction);
    a->Visit("dof", &dof);
    a->VisitIfSet("sign", &sign);
  }
};

struct UffLabelFields {
  int mode = 0;  // dataset 55's mode number
  std::string label;
  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("mode", &mode);
    a->Visit("label", &label);
  }
};

// The map file, field by field (docs/inputs.md).
struct UffMapFields {
  std::string format = kUffMapFormat;
  std::string name;
  std::optional<std::string> description;
  std::vector<UffChannelFields> channels;
  std::optional<std::vector<UffLabelFields>> labels;  // absent: the model labels every mode
  std::optional<std::vector<std::string>> known;      // parameters of --parameters written known
  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("format", &format);
    a->Visit("name", &name);
    a->VisitIfSet("description", &description);
    a->Visit("channels", &channels);
    a->VisitIfSet("labels", &labels);
    a->VisitIfSet("known", &known);
  }
};

struct UffMap {
  struct Channel {
    int node = 0, direction = 0;
    Dof dof = Dof::kXb;
    double sign = 1;
  };
  std::string name, description;
  std::vector<Channel> channels;
  std::map<int, ModeLabel> labels;  // mode number -> label
  std::vector<Param> known;
};

bool ParseUffMap(const std::string& text, const std::string& path, UffMap* map, LoadError* error);
bool LoadUffMap(const std::string& path, UffMap* map, LoadError* error);

// A mode the model labelled (the map did not): its index in dataset.modes
// and, where its shape decided the label, the MAC with the model mode that
// named it.
struct UffModelLabel {
  int mode = 0;
  std::optional<double> mac;
};

// What an import made and said.
struct UffImport {
  Dataset dataset;
  std::vector<std::string> notes;     // units, skipped data, how each mode was labelled
  std::vector<UffModelLabel> by_model;
  std::vector<std::string> warnings;  // labels that rest on a poor fit (estimation/label_by_fit.h)
};

// The modes of `file`'s dataset-55 records under `map`, as a format-1
// dataset. `p` (may be null): the parameters the model labels with, by the
// pairing of datasets/pairing.h with the model's modes the map's labels left
// (shapes compared under `convention`), and the dataset's known (map.known)
// and initial (the rest) values. Complex shapes are made real as the
// contract's §2 (largest component real); translations are converted to
// metres by dataset 164. False, with `error` naming the map field or the UFF
// record, where a mode cannot be labelled or read, or a mapped node or
// direction is not in a mode's record.
bool UffToDataset(const UffFile& file, const UffMap& map, const Parameters* p, UffImport* out,
                  LoadError* error, ShapeConvention convention = ShapeConvention::kContract);

}  // namespace ringid

#endif  // RINGID_DATASETS_UFF_DATASET_H_
