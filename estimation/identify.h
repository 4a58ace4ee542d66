// Identification of rigid-ring parameters from modal data.
#ifndef RINGID_ESTIMATION_IDENTIFY_H_
#define RINGID_ESTIMATION_IDENTIFY_H_

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "datasets/dataset.h"
#include "datasets/measurement.h"
#include "estimation/frf_fits.h"
#include "estimation/options.h"
#include "estimation/status.h"
#include "estimation/types.h"
#include "estimation/uncertainty_result.h"
#include "model/plausibility.h"
#include "model/rigid_ring_model.h"

namespace ringid {

class Problem;  // estimation/problem.h

struct IdentifyOptions {
  Method method = Method::kLevenbergMarquardt;
  // Fits from the dataset's initial point, from the point that matches the
  // measured frequencies, and from points scattered log-uniformly within a
  // factor start_factor of it (estimation/starts.h); the lowest cost wins.
  int starts = 6;
  double start_factor = 3;
  unsigned seed = 1;
  // Free coordinates stay within a factor bound_factor of their start,
  // those of parameters with `bounds` within them.
  double bound_factor = 1e3;
  Bounds bounds;
  int max_iterations = 200;  // Levenberg-Marquardt, per start
  // Levenberg-Marquardt stops when no step changes chi-square by more than
  // this (0: only Ceres' relative tolerances of 1e-14).
  double stop_chi_square = kStopChiSquare;
  SimplexOptions simplex;
  ResidualOptions residuals;
  UncertaintyOptions uncertainty;
  // Starts (and diagnose's candidate effects) fitted at once, at most
  // kMaxThreads; 0: one thread per core. Results are the same on any number.
  int threads = 0;
  static constexpr int kMaxThreads = 256;
  // False: the fit alone (status, x, parameters, cost, the starts), without
  // the uncertainty, estimates and mode fits after it: for a fit whose point
  // is all its caller uses (the modal stage of an FRF start).
  bool analysis = true;

  bool IsValid(std::string* why) const;
};

// A prior and the data disagree when the estimate sits further than this many
// prior standard deviations from the prior's center (beyond its 99.7 % range).
inline constexpr double kPriorConflictZ = 3.0;

// A known (fixed) parameter that a free one's class rests on: freed, it
// would take that class with it, as a standing test measures only
// K_cx/sigma_cx (estimation/structure.h, FindStructuralFreedom), or would
// leave it practically_no (AddPracticalDependence, estimation/identify.cc).
struct KnownCondition {
  Param known = Param::m_b;
  double value = 0;      // the known value it was held at (first condition)
  std::string measured;  // what the data measure of the two: "K_cx/sigma_cx"
  // True: the model cannot tell them apart; false: the data hardly can
  // (freed, it would make this one practically_no).
  bool structural = true;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("known", &known);
    a->Visit("value", &value);
    a->Visit("measured", &measured);
    a->Visit("structural", &structural);
  }
};

// What decides a value that has a prior, from its prior_share: the prior
// where it keeps over kPriorDecides of the prior variance, the data where
// under kDataDecides is left, else both.
enum class DecidedBy { kData, kDataAndPrior, kPrior };
template <>
struct EnumNames<DecidedBy> {
  static constexpr std::array<const char*, 3> kNames = {"data", "data_and_prior", "prior"};
};
inline constexpr double kPriorDecides = 0.5;
inline constexpr double kDataDecides = 0.1;
// "the data", "data and prior", "the prior".
const char* DecidedByWords(DecidedBy d);

struct ParameterEstimate {
  ParameterKey key;  // the parameter, and its condition when per-condition
  double value = 0;
  bool free = false;
  std::optional<Param> tied_to;
  Identifiability identifiable = Identifiability::kYes;
  std::string reason;
  std::optional<double> std;  // physical units; none where not defined
  // Wald 95 %, symmetric in the coordinate fitted (ParameterSetup::Interval95);
  // none where std is none.
  std::optional<std::pair<double, double>> interval_95;
  // With a prior: posterior over prior variance (Laplace), near 1 where the
  // prior decides the value, near 0 where the data do.
  std::optional<double> prior_share;
  std::optional<DecidedBy> decided_by;  // with a prior, from prior_share
  // With a prior: the estimate's distance from the prior's center in prior
  // standard deviations (of the log for a lognormal prior), signed.
  std::optional<double> prior_z;
  // The fit stopped on this side of the parameter's box: not an interior
  // optimum, so its std and class describe the box, not the data.
  std::optional<BoundSide> on_bound;
  // The known parameters its class rests on (a free parameter classed yes or
  // practically_no); empty when none does.
  std::vector<KnownCondition> conditional_on;

  Param param() const { return key.param; }
  // "given sigma_cx = 0.1 m (known): the data measure K_cx/sigma_cx", one
  // clause per known parameter; none when conditional_on is empty.
  std::optional<std::string> Condition() const;
  // The data pull the estimate further from its prior than the prior allows
  // (|prior_z| > kPriorConflictZ): one of the two is wrong.
  bool PriorConflict() const;

  template <class Archive>  // keyed by key in IdentifyResult
  void Serialize(Archive* a) {
    a->Visit("value", &value);
    a->Derived("unit", std::string(Info(key.param).unit));
    a->Visit("free", &free);
    a->VisitIfSet("tied_to", &tied_to);
    a->Visit("std", &std);
    a->Visit("interval_95", &interval_95);
    a->Visit("identifiable", &identifiable);
    a->Visit("reason", &reason);
    a->VisitIfSet("prior_share", &prior_share);
    a->VisitIfSet("decided_by", &decided_by);
    a->VisitIfSet("prior_z", &prior_z);
    a->VisitIfSet("on_bound", &on_bound);
    a->Visit("conditional_on", &conditional_on);
    a->Derived("condition", Condition());
  }
};

struct ModeFit {
  std::optional<std::string> condition;  // format 2: the condition's name
  std::optional<double> speed_m_s;       // format 2: the condition's speed
  ModeLabel label;     // the measured mode's label
  ModeLabel model_label;  // the label of the model mode it was paired with
  double measured_hz = 0;
  double measured_sigma_hz = 0;  // the sigma it was weighted by
  double model_hz = 0;
  std::optional<double> measured_damping;
  double model_damping = 0;
  std::optional<double> mac;  // where a shape was measured
  // MAC against every model mode (by label), where a shape was measured.
  std::map<ModeLabel, double> mac_all;

  template <class Archive>
  void Serialize(Archive* a) {
    a->VisitIfSet("condition", &condition);
    a->VisitIfSet("speed_m_s", &speed_m_s);
    a->Visit("label", &label);
    a->Visit("measured_hz", &measured_hz);
    a->Visit("measured_sigma_hz", &measured_sigma_hz);
    a->Visit("model_hz", &model_hz);
    a->Visit("model_label", &model_label);
    a->Visit("model_damping_ratio", &model_damping);
    a->VisitIfSet("measured_damping_ratio", &measured_damping);
    a->VisitIfSet("mac", &mac);
    a->Visit("mac_all", &mac_all);
  }
};

// A measurement other than a mode's (a static stiffness) against the fitted
// model (Measurement::Compared).
struct MeasurementFit {
  Quantity quantity = Quantity::kStatic;
  std::string name;                      // "static vertical stiffness"
  std::optional<std::string> condition;  // formats 2 and 3: the condition's name
  double measured = 0;
  double sigma = 0;  // the sigma it was weighted by
  double model = 0;
  std::string unit;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("quantity", &quantity);
    a->Visit("name", &name);
    a->VisitIfSet("condition", &condition);
    a->Visit("measured", &measured);
    a->Visit("sigma", &sigma);
    a->Visit("model", &model);
    a->Visit("unit", &unit);
    a->Derived("residual_sigma", (model - measured) / sigma);
  }
};

// One mode of the fitted model against forward speed (a Campbell diagram).
struct SpeedCurve {
  ModeLabel label;
  std::vector<double> speed_m_s;
  std::vector<double> frequency_hz;   // damped, NaN where the mode is overdamped
  std::vector<double> damping_ratio;  // NaN where the mode is overdamped

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("label", &label);
    a->Visit("speed_m_s", &speed_m_s);
    a->Visit("frequency_hz", &frequency_hz);
    a->Visit("damping_ratio", &damping_ratio);
  }
};

// Below this p-value a fit is poor: the model misses what the data show.
inline constexpr double kPoorFitP = 0.01;

// Whether the model fits the data: the chi-square of the weighted residuals
// (prior rows included) against its degrees of freedom.
struct FitQuality {
  double chi_square = 0;        // 2 cost
  // Residuals minus the Jacobian's rank minus one per compared shape (its
  // scale is fitted inside the residual).
  int degrees_of_freedom = 0;
  std::optional<double> p_value;  // P(chi-square >= chi_square); none without dof
  bool poor = false;            // p_value < kPoorFitP
  std::string verdict;          // the above in words

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("chi_square", &chi_square);
    a->Visit("degrees_of_freedom", &degrees_of_freedom);
    a->Visit("p_value", &p_value);
    a->Visit("poor", &poor);
    a->Visit("verdict", &verdict);
  }
};
FitQuality AssessFit(double cost, int residuals, int rank, int shape_scales);

// Starts whose chi-square lies within this of the best reached the same
// optimum (cost within 0.5).
inline constexpr double kSameOptimumChiSquare = 1.0;
// Starts at the best chi-square disagree on a coordinate when they differ by
// more than this in it (1 % of a positive parameter's value).
inline constexpr double kStartsDisagree = 0.01;

// Whether the starts found one best point (issue 21): how many reached the
// best chi-square, and where those that did still differ.
struct StartAgreement {
  int at_best = 0;  // starts within kSameOptimumChiSquare of the best
  int of = 0;       // starts with a usable fit
  // Free coordinates on which the starts at the best disagree: the largest
  // over the smallest value among them (the largest difference in units of
  // the typical scale for a parameter that may be zero or negative).
  std::map<std::string, double> disagree;
  std::string verdict;  // the above in words

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("at_best", &at_best);
    a->Visit("of", &of);
    a->Visit("disagree", &disagree);
    a->Visit("verdict", &verdict);
  }
};

struct IdentifyResult {
  // Success: a fit was obtained, and message says how the winning start
  // stopped; invalid input: nothing was fitted.
  Status status;
  bool converged = false;   // the winning start met its convergence test
  // Headline warnings, one sentence each: the pairing of measured with model
  // modes at the start and at the best fit (ModalResiduals::PairingWarnings),
  // data with fewer observables than free parameters, and a best start that
  // did not converge, with what to try.
  std::vector<std::string> warnings;
  Method method = Method::kLevenbergMarquardt;
  FrequencyWeighting frequency_weighting = FrequencyWeighting::kSigma;
  double cost = 0;          // 1/2 sum of squared weighted residuals
  FitQuality fit;
  long evaluations = 0;     // model solutions, all starts
  double seconds = 0;
  int starts = 0;
  std::vector<double> start_costs;
  std::vector<StartOrigin> start_origins;  // beside start_costs
  StartAgreement start_agreement;
  Parameters parameters;  // of the first condition
  Eigen::VectorXd x;      // the fitted coordinates (not in the report)
  std::vector<ParameterEstimate> estimates;  // model parameters, in order
  // Values of `estimates` outside their physical range (docs/plausibility.md).
  std::vector<PlausibilityFlag> plausibility;
  Uncertainty uncertainty;
  std::vector<std::string> coordinate_names;
  std::vector<ModeFit> modes;
  // Format 3: the other measurements (static stiffnesses); unset where none.
  std::optional<std::vector<MeasurementFit>> measurements;
  // Measured FRFs: each function against the fitted model (FrfFits); unset
  // where the dataset has none.
  std::optional<std::vector<FrfFit>> frfs;
  // Format 2 with a condition at speed: every mode of the fitted model (the
  // first condition's values) from standstill to 1.25 times the highest
  // speed; empty otherwise.
  std::vector<SpeedCurve> speed_curves;
  // Eq. (19) over in-plane modes and eq. (20) over out-of-plane modes:
  // sum ((f_exp - f_cal) / f_exp)^2; NaN where the plane has no mode.
  double relative_error_in_plane = 0;
  double relative_error_out_of_plane = 0;

  std::string BriefReport() const;
  std::string FullReport() const;
  // One sentence naming each parameter whose prior the data contradict
  // (ParameterEstimate::PriorConflict), empty when there is none.
  std::string PriorConflicts() const;
  // One sentence naming each parameter on a bound, empty when there is none.
  std::string OnBounds() const;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("method", &method);
    a->Visit("frequency_weighting", &frequency_weighting);
    status.Serialize(a);
    a->Visit("warnings", &warnings);
    a->Visit("converged", &converged);
    a->Visit("cost", &cost);
    a->Visit("fit", &fit);
    a->Visit("evaluations", &evaluations);
    a->Visit("seconds", &seconds);
    a->Visit("starts", &starts);
    a->Visit("start_costs", &start_costs);
    a->Visit("start_origins", &start_origins);
    a->Visit("start_agreement", &start_agreement);
    a->Group("relative_error", [&](auto* g) {
      g->Visit("in_plane_eq19", &relative_error_in_plane);
      g->Visit("out_of_plane_eq20", &relative_error_out_of_plane);
    });
    a->VisitKeyed("parameters", &estimates, &ParameterEstimate::key);
    a->Visit("plausibility", &plausibility);
    a->Group("covariance", [&](auto* g) {
      g->Visit("names", &coordinate_names);
      g->Derived("coordinates", std::string("log for positive parameters"));
      uncertainty.Serialize(g);
    });
    a->Visit("modes", &modes);
    a->VisitIfSet("measurements", &measurements);
    a->VisitIfSet("frfs", &frfs);
    a->Visit("speed_curves", &speed_curves);
  }
};

// The identification of `problem`: its model, dataset and residual options
// (options.residuals is not read; the problem was made with its own). Never
// aborts: invalid setups and numerical failures come back in result->status.
void Identify(const Problem& problem, const IdentifyOptions& options, IdentifyResult* result);
// The same on the problem Problem::Create makes of model, dataset and
// options.residuals.
void Identify(const ModalModel& model, const Dataset& dataset,
              const IdentifyOptions& options, IdentifyResult* result);

}  // namespace ringid

#endif  // RINGID_ESTIMATION_IDENTIFY_H_
