// What the data determines, at the fitted point: rank and conditioning,
// per-parameter classes with Wald and profile-likelihood intervals, the
// combinations left free, collinear parameter subsets (Brun et al. 2001),
// the largest identifiable subset, and which extra observation would help.
#ifndef RINGID_ESTIMATION_IDENTIFIABILITY_H_
#define RINGID_ESTIMATION_IDENTIFIABILITY_H_

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "estimation/identify.h"

namespace ringid {

class Problem;

struct IdentifiabilityOptions {
  IdentifyOptions fit;  // the identification the analysis starts from
  // Profiles step each coordinate away from the optimum, re-optimising the
  // others, until 2 (cost - cost_min) passes the chi-square(1) 95 % point
  // 3.841, at most profile_steps steps a side, steps growing from
  // profile_first_step by profile_growth (coordinate units, log for
  // positive parameters); the crossing is then bisected with a refit at
  // each midpoint. A step whose refit fails is halved a few times.
  int profile_steps = 12;
  double profile_first_step = 0.02;
  double profile_growth = 1.6;
  // Whether the profiles run at all (the report's `profiles` says why);
  // the coordinates' profiles share fit.threads.
  Profiles profiles = Profiles::kAuto;
  // Pairs whose normalised Jacobian columns give a collinearity index
  // (Brun et al. 2001) above this are not separately identifiable.
  double collinearity_threshold = 1e3;
  // Directions with singular value below this fraction of the largest are
  // reported as near-null combinations (the null ones always are).
  double near_null = 1e-3;
  // Each combination is listed once: a direction in the span of the
  // structurally free directions, or differing from a listed one by such a
  // direction and a multiple, is not listed again. Within this: the sine of
  // the angle to that span, or between the parts outside it.
  double same_direction = 1e-3;
  // Sigmas of the candidate observations the advice ranks.
  double advice_damping_sigma = 0.02;
  double advice_shape_sigma = 0.05;
  double advice_known_relative_sigma = 0.05;  // a known value to 5 %
  // New test conditions the advice weighs (docs/conventions.md §7): the
  // measured modes again, rolling on a drum at each speed, and standing at
  // the load F_cz0 times advice_load_factor (where F_cz0 is known).
  std::vector<double> advice_speeds_m_s = {3, 6, 12, 25};
  double advice_load_factor = 1.5;
  int advice_per_parameter = 3;
  // Called as the analysis goes: steps done of total (the fit, each
  // coordinate's profile, the rest), from the calling thread.
  std::function<void(int done, int total)> on_step;

  bool IsValid(std::string* why) const;
};

// Each side is closed (lower/upper: a refitted point where 2 delta cost is
// 3.841 to within 0.02), jumped (*_jump_at), failed (*_failed_at) or open
// (none: the scan reached its last step or the box under the threshold). A
// jump is never a bound: 2 delta cost leaps over the threshold between two
// refitted points 1e-6 apart in coordinates, and a warm-started walk from
// the last profile point under it meets the same leap (a refit that merely
// failed is retried so and the scan goes on), so the fit moves to another
// optimum there rather than rising through the threshold.
struct ProfileInterval {
  bool computed = false;
  std::optional<double> lower, upper;  // physical units; none: did not close
  // Physical value, the first over the threshold, where the profile jumps to
  // another optimum, on a side that did not close; none otherwise.
  std::optional<double> lower_jump_at, upper_jump_at;
  // Physical value nearest the optimum where no refit was possible (from
  // no start a finite cost), on a side that did not close; none otherwise.
  std::optional<double> lower_failed_at, upper_failed_at;
  std::vector<std::pair<double, double>> curve;  // (value, 2 delta cost), every point refitted

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("computed", &computed);
    a->Visit("lower", &lower);
    a->Visit("upper", &upper);
    a->Visit("lower_jump_at", &lower_jump_at);
    a->Visit("upper_jump_at", &upper_jump_at);
    a->Visit("lower_failed_at", &lower_failed_at);
    a->Visit("upper_failed_at", &upper_failed_at);
    a->Visit("curve_value_delta_chi2", &curve);
  }
};

// Whether the profile intervals were computed, and why or why not.
struct ProfilesRun {
  bool computed = false;
  std::string why;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("computed", &computed);
    a->Visit("why", &why);
  }
};

struct ParameterIdentifiability {
  ParameterKey key;
  double value = 0;
  Identifiability identifiable = Identifiability::kNo;
  std::string reason;
  std::optional<double> std;
  std::optional<std::pair<double, double>> wald_95;
  ProfileInterval profile_95;

  Param param() const { return key.param; }

  template <class Archive>  // keyed by key in IdentifiabilityResult
  void Serialize(Archive* a) {
    a->Visit("value", &value);
    a->Visit("identifiable", &identifiable);
    a->Visit("reason", &reason);
    a->Visit("std", &std);
    a->Visit("wald_95", &wald_95);
    a->Visit("profile", &profile_95);
    a->Derived("profile_95", profile_95.computed
                                 ? std::optional(std::pair(profile_95.lower, profile_95.upper))
                                 : std::nullopt);
  }
};

struct Combination {
  std::string text;            // e.g. "log K_cx + log sigma_cx"
  std::string meaning;         // e.g. "only K_cx / sigma_cx is determined"
  double singular_value = 0;   // of the direction (0 for a structural pair)
  std::vector<std::pair<std::string, double>> terms;  // coordinate, coefficient

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("text", &text);
    a->Visit("meaning", &meaning);
    a->Visit("singular_value", &singular_value);
    a->Visit("terms", &terms);
  }
};

struct CollinearSubset {
  std::vector<std::string> names;
  double index = 0;  // collinearity index; inf for exact collinearity

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("parameters", &names);
    a->Visit("collinearity_index", &index);
  }
};

struct Advice {
  std::string parameter;    // the parameter it would help
  std::string observation;  // e.g. "damping ratio of rotation_anti_phase"
  double information_gain = 0;  // 1/2 log(var before / var after), nats
  // The parameter's relative standard deviation with it (linearised): "would
  // determine k_by to 4 %".
  double relative_std_after = 0;
  bool makes_identifiable = false;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("parameter", &parameter);
    a->Visit("observation", &observation);
    a->Visit("information_gain_nats", &information_gain);
    a->Visit("relative_std_after", &relative_std_after);
    a->Visit("makes_identifiable", &makes_identifiable);
  }
};

struct IdentifiabilityResult {
  Status status;
  IdentifyResult fit;
  int rank = 0;
  int num_residuals = 0;
  double condition_number = 0;
  Eigen::VectorXd singular_values;
  std::string rank_explanation;
  std::vector<std::string> coordinate_names;
  std::vector<ParameterIdentifiability> parameters;  // free coordinates
  ProfilesRun profiles;
  std::vector<Combination> combinations;
  Eigen::MatrixXd correlation;  // empty when the covariance is unavailable
  std::vector<CollinearSubset> collinear_pairs;
  std::vector<std::string> identifiable_subset;  // rank-revealing QR order
  std::vector<Advice> advice;
  double seconds = 0;

  std::string FullReport() const;

  template <class Archive>
  void Serialize(Archive* a) {
    status.Serialize(a);
    a->Visit("rank", &rank);
    a->Visit("num_residuals", &num_residuals);
    a->Visit("condition_number", &condition_number);
    a->Visit("rank_explanation", &rank_explanation);
    a->Visit("singular_values", &singular_values);
    a->Visit("coordinates", &coordinate_names);
    a->VisitKeyed("parameters", &parameters, &ParameterIdentifiability::key);
    a->Visit("profiles", &profiles);
    a->Visit("combinations", &combinations);
    a->Visit("correlation", &correlation);
    a->Visit("collinear_pairs", &collinear_pairs);
    a->Visit("identifiable_subset", &identifiable_subset);
    a->Visit("advice", &advice);
    a->Visit("seconds", &seconds);
  }
};

// What the data determine at `fit`, an identification of `problem`
// (Identify(problem, options.fit, &fit)); options.fit.residuals is not read.
void AnalyzeIdentifiability(const Problem& problem, const IdentifyResult& fit,
                            const IdentifiabilityOptions& options, IdentifiabilityResult* result);
// The same after identifying the problem Problem::Create makes of model,
// dataset and options.fit.residuals.
void AnalyzeIdentifiability(const ModalModel& model, const Dataset& dataset,
                            const IdentifiabilityOptions& options,
                            IdentifiabilityResult* result);

}  // namespace ringid

#endif  // RINGID_ESTIMATION_IDENTIFIABILITY_H_
