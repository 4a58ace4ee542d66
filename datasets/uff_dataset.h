// A test lab's UFF modes (dataset 55) as a ringid dataset (docs/uff.md): a
// map (ringid-uff-map/1 or /2) says which node and direction is which degree
// of freedom, with sign, and which mode is which label where the user knows
// it; the model labels the others by their shapes (contract §2 pairing).
// Format 2 adds the points that place the nodes of its FRFs (dataset 58,
// datasets/uff_frf.h).
#ifndef RINGID_DATASETS_UFF_DATASET_H_
#define RINGID_DATASETS_UFF_DATASET_H_

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "datasets/dataset.h"
#include "datasets/frf.h"
#include "datasets/measurement_options.h"
#include "datasets/uff.h"
#include "model/archive.h"
#include "model/parameters.h"

namespace ringid {

inline constexpr const char* kUffMapFormat = "ringid-uff-map/1";
inline constexpr const char* kUffMapFormat2 = "ringid-uff-map/2";

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

// Format 2: where a node is, for the FRFs that name it (contract §9).
struct UffPointFields {
  int node = 0;
  FrfBody on = FrfBody::kBelt;
  std::optional<std::vector<double>> point_m;  // ringid's axes; absent: dataset 15's node
  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("node", &node);
    a->Visit("on", &on);
    a->VisitIfSet("point_m", &point_m);
  }
};

// Format 2: the units of every FRF where the file's exponents and labels do
// not say them (datasets/uff_frf.h's unit names).
struct UffUnitFields {
  std::optional<std::string> response;   // record 9: a motion unit ("g", "mm/s^2", ...)
  std::optional<std::string> reference;  // record 10: a force unit ("N", "lbf", ...)
  template <class Archive>
  void Serialize(Archive* a) {
    a->VisitIfSet("response", &response);
    a->VisitIfSet("reference", &reference);
  }
};

// The map file, field by field (docs/inputs.md). The format, read first,
// decides the fields after.
struct UffMapFields {
  std::string format = kUffMapFormat;
  std::string name;
  std::optional<std::string> description;
  std::vector<UffChannelFields> channels;  // format 1: required
  std::optional<std::vector<UffChannelFields>> channels2;  // format 2 "channels": optional
  std::optional<std::vector<UffPointFields>> points;       // format 2
  std::optional<std::vector<std::string>> axes;            // format 2: ringid's x, y, z in the lab's
  std::optional<UffUnitFields> units;                      // format 2
  std::optional<int> averages;                             // format 2: of the coherences
  std::optional<std::vector<UffLabelFields>> labels;  // absent: the model labels every mode
  std::optional<std::vector<std::string>> known;      // parameters of --parameters written known
  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("format", &format);
    a->Visit("name", &name);
    a->VisitIfSet("description", &description);
    if (format == kUffMapFormat2) {
      a->VisitIfSet("channels", &channels2);
      a->VisitIfSet("points", &points);
      a->VisitIfSet("axes", &axes);
      a->VisitIfSet("units", &units);
      a->VisitIfSet("averages", &averages);
    } else {
      a->Visit("channels", &channels);
    }
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
  // Format 2: a node's place; its directions come with each function.
  struct Point {
    int node = 0;
    FrfBody on = FrfBody::kBelt;
    std::optional<std::array<double, 3>> point_m;  // ringid's axes, m; else dataset 15's
  };
  std::string name, description;
  std::vector<Channel> channels;
  std::map<int, ModeLabel> labels;  // mode number -> label
  std::vector<Param> known;
  std::vector<Point> points;
  // ringid's (x forward, y right, z down) = axes * the lab's: each row a
  // lab axis with its sign. The identity unless the map's `axes` says.
  std::array<std::array<double, 3>, 3> axes{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  std::string response_unit, reference_unit;  // the map's units; empty: the file's
  std::optional<int> averages;
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

// The values of `p` as `d`'s known (those of map.known) and initial (the rest).
void WriteUffParameters(const Parameters& p, const UffMap& map, Dataset* d);

}  // namespace ringid

#endif  // RINGID_DATASETS_UFF_DATASET_H_
