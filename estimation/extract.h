// The modes in a dataset's FRFs as a modal dataset that identify reads
// (issue 37): each condition's physical poles (estimation/plscf.h), labelled
// by fit from the dataset's initial values as the modal stage of a fit to
// FRFs labels them (estimation/frf_start.h), so that the modal and the FRF
// routes start from the same measurements.
#ifndef RINGID_ESTIMATION_EXTRACT_H_
#define RINGID_ESTIMATION_EXTRACT_H_

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "datasets/dataset.h"
#include "estimation/plscf.h"
#include "estimation/status.h"
#include "model/modal.h"
#include "model/rigid_ring_model.h"

namespace ringid {

// A physical pole of a condition's FRFs.
struct ExtractedPole {
  int condition = 0;
  double frequency_hz = 0;  // damped (contract §2)
  double damping_ratio = 0;
  int stable_orders = 0;    // orders of the stabilisation diagram that hold it
  // Its label where it went into the dataset (the model has seven modes per
  // condition: the strongest are kept), and whether the outputs gave it a
  // shape on the model's coordinates.
  std::optional<ModeLabel> label;
  bool shape = false;
  // Standard errors, where an estimator gives them (pLSCF does not).
  std::optional<double> frequency_sigma_hz, damping_sigma;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("condition", &condition);
    a->Visit("frequency_hz", &frequency_hz);
    a->VisitIfSet("frequency_sigma_hz", &frequency_sigma_hz);
    a->Visit("damping_ratio", &damping_ratio);
    a->VisitIfSet("damping_sigma", &damping_sigma);
    a->Visit("stable_orders", &stable_orders);
    a->Visit("label", &label);
    a->Visit("shape", &shape);
  }
};

// What a condition's modes came from: its FRFs and their extraction (the
// stabilisation diagram, the physical poles, LSFD per function).
struct ExtractedCondition {
  int condition = 0;
  Frf frf;
  PlscfResult plscf;
};

// A parameter both routes determine (classed yes by each): fitted directly
// to the FRFs and, through extraction, to the modal dataset (its masses
// known), each with its standard error.
struct RouteRow {
  std::string parameter;  // as identify's report names it
  double direct = 0, direct_std = 0;
  double modal = 0, modal_std = 0;

  // The difference in combined standard errors, and how much wider the
  // modal route's interval is.
  double DifferenceSd() const { return std::abs(direct - modal) / std::hypot(direct_std, modal_std); }
  double StdRatio() const { return modal_std / direct_std; }
  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("parameter", &parameter);
    a->Visit("direct", &direct);
    a->Visit("direct_std", &direct_std);
    a->Visit("modal", &modal);
    a->Visit("modal_std", &modal_std);
    a->Derived("difference_sd", DifferenceSd());
    a->Derived("std_ratio", StdRatio());
  }
};

struct ExtractResult {
  Status status;
  Dataset dataset;  // the modes, the FRF dataset's conditions, known, initial, ties
  std::vector<ExtractedPole> poles;  // every condition's, ascending frequency in each
  std::vector<std::string> notes;    // what the dataset assumes
  std::vector<ExtractedCondition> conditions;  // each with an frf block
  // The two routes side by side (issue 37 item 5): identify on the FRFs (the
  // fit that names the modes) and on `dataset`; empty where the latter fails.
  std::vector<RouteRow> routes;
};

// The modes in d's FRFs under `plscf`: each condition's physical poles, the
// strongest (as many as the model has) labelled by fit from d's initial
// values (the modal stage, its labels tried in every order where the outputs
// give no shape) with their shapes where the outputs determine them; the FRF
// blocks dropped, the masses and inertias made known at their initial values
// (modes carry no modal mass). Invalid input: bad options, no frf block, no
// physical pole; failed: the model pairs none of them or its fit fails.
void ExtractModalDataset(const ModalModel& model, const Dataset& d, const PlscfOptions& plscf,
                         ExtractResult* r);

}  // namespace ringid

#endif  // RINGID_ESTIMATION_EXTRACT_H_
