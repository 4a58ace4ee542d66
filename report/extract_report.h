// The report of `ringid extract --report` (issue 37, operations/extract.h):
// what the modal dataset came from. Per condition, pLSCF's stabilisation
// diagram (estimation/plscf.h) and each measured function against its LSFD
// synthesis (estimation/lsfd.h) with their FRAC; the physical poles and the
// notes as extract found them.
#ifndef RINGID_REPORT_EXTRACT_REPORT_H_
#define RINGID_REPORT_EXTRACT_REPORT_H_

#include <optional>
#include <string>
#include <vector>

#include "estimation/extract.h"
#include "estimation/frf_fits.h"
#include "estimation/status.h"
#include "model/modal.h"
#include "report/report.h"

namespace ringid {

// A pole of one order of the stabilisation diagram (PlscfPole): stable where
// it is in frequency, damping and participation vector, each against the
// nearest pole of the order below (PlscfOptions' tolerances).
struct DiagramPole {
  double frequency_hz = 0;  // damped (contract §2)
  double damping_ratio = 0;
  bool stable_frequency = false, stable_damping = false, stable_vector = false;

  bool stable() const { return stable_frequency && stable_damping && stable_vector; }
  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("frequency_hz", &frequency_hz);
    a->Visit("damping_ratio", &damping_ratio);
    a->Visit("stable_frequency", &stable_frequency);
    a->Visit("stable_damping", &stable_damping);
    a->Visit("stable_vector", &stable_vector);
  }
};

// The poles of one model order (Im λ > 0), ascending frequency.
struct DiagramOrder {
  int order = 0;
  std::vector<DiagramPole> poles;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("order", &order);
    a->Visit("poles", &poles);
  }
};

// One pLSCF fit of the condition (PlscfBlock): its inputs and outputs by
// name, and its stabilisation diagram.
struct ExtractBlock {
  std::vector<std::string> inputs, outputs;
  std::vector<DiagramOrder> diagram;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("inputs", &inputs);
    a->Visit("outputs", &outputs);
    a->Visit("diagram", &diagram);
  }
};

// One condition's extraction.
struct ExtractCondition {
  int condition = 0;                // its index in the dataset, as ExtractedPole's
  std::optional<std::string> name;  // where the dataset names its conditions
  Status status;                    // of its pLSCF
  std::vector<ExtractBlock> blocks;  // one where every output is measured at every input
  // The physical real poles σ (1/s, PlscfResult::real_poles): at speed, the
  // slip lags' roots in the band (docs/rolling.md §2: near -V / σ_c).
  std::vector<double> real_poles_per_s;
  // Each measured function (the frf block's order) on the lines pLSCF used,
  // against the LSFD synthesis at the physical poles (`model_re`,
  // `model_im`); chi2 with the measured sigma, FRAC between the two.
  std::vector<FrfFit> functions;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("condition", &condition);
    a->VisitIfSet("name", &name);
    status.Serialize(a);
    a->Visit("blocks", &blocks);
    a->Visit("real_poles_per_s", &real_poles_per_s);
    a->Visit("functions", &functions);
  }
};

struct ExtractBody {
  std::string dataset;  // the FRF dataset, as extract was given it
  Status status;
  std::vector<ExtractedPole> poles;  // every condition's physical poles
  std::vector<ExtractCondition> conditions;  // each with an frf block
  std::vector<std::string> notes;  // what the modal dataset assumes
  std::vector<RouteRow> routes;    // the direct and the modal route side by side

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("dataset", &dataset);
    status.Serialize(a);
    a->Visit("poles", &poles);
    a->Visit("conditions", &conditions);
    a->Visit("notes", &notes);
    a->Visit("routes", &routes);
  }
};

using ExtractReport = Report<ReportKind::kExtract, ExtractBody>;

}  // namespace ringid

#endif  // RINGID_REPORT_EXTRACT_REPORT_H_
