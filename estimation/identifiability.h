// What the data determines, at the fitted point: rank and conditioning,
// per-parameter classes with Wald and profile-likelihood intervals, the
// combinations left free, collinear parameter subsets (Brun et al. 2001),
// the largest identifiable subset, and which extra observation would help.
#ifndef RINGID_ESTIMATION_IDENTIFIABILITY_H_
#define RINGID_ESTIMATION_IDENTIFIABILITY_H_

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "estimation/identify.h"

namespace ringid {

struct IdentifiabilityOptions {
  IdentifyOptions fit;  // the identification the analysis starts from
  // Profiles step each coordinate away from the optimum, re-optimising the
  // others, until 2 (cost - cost_min) passes the chi-square(1) 95 % point
  // 3.841, at most profile_steps steps a side, steps growing from
  // profile_first_step by profile_growth (coordinate units, log for
  // positive parameters).
  int profile_steps = 12;
  double profile_first_step = 0.02;
  double profile_growth = 1.6;
  // Pairs whose normalised Jacobian columns give a collinearity index
  // (Brun et al. 2001) above this are not separately identifiable.
  double collinearity_threshold = 1e3;
  // Directions with singular value below this fraction of the largest are
  // reported as near-null combinations (the null ones always are).
  double near_null = 1e-3;
  // Sigmas of the candidate observations the advice ranks.
  double advice_damping_sigma = 0.02;
  double advice_shape_sigma = 0.05;
  double advice_known_relative_sigma = 0.05;  // a known value to 5 %
  int advice_per_parameter = 3;

  bool IsValid(std::string* why) const;
};

struct ProfileInterval {
  bool computed = false;
  std::optional<double> lower, upper;  // physical units; none: did not close
  std::vector<std::pair<double, double>> curve;  // (value, 2 delta cost)
};

struct ParameterIdentifiability {
  Param param;
  double value = 0;
  Identifiability identifiable = Identifiability::kNo;
  std::string reason;
  std::optional<double> std;
  std::optional<std::pair<double, double>> wald_95;
  ProfileInterval profile_95;
};

struct Combination {
  std::string text;            // e.g. "log K_cx + log sigma_cx"
  std::string meaning;         // e.g. "only K_cx / sigma_cx is determined"
  double singular_value = 0;   // of the direction (0 for a structural pair)
  std::vector<std::pair<std::string, double>> terms;  // coordinate, coefficient
};

struct CollinearSubset {
  std::vector<std::string> names;
  double index = 0;  // collinearity index; inf for exact collinearity
};

struct Advice {
  std::string parameter;    // the parameter it would help
  std::string observation;  // e.g. "damping ratio of rotation_anti_phase"
  double information_gain = 0;  // 1/2 log(var before / var after), nats
  bool makes_identifiable = false;
};

struct IdentifiabilityReport {
  bool success = false;
  std::string message;
  IdentifySummary fit;
  int rank = 0;
  int num_residuals = 0;
  double condition_number = 0;
  Eigen::VectorXd singular_values;
  std::string rank_explanation;
  std::vector<std::string> coordinate_names;
  std::vector<ParameterIdentifiability> parameters;  // free coordinates
  std::vector<Combination> combinations;
  Eigen::MatrixXd correlation;  // empty when the covariance is unavailable
  std::vector<CollinearSubset> collinear_pairs;
  std::vector<std::string> identifiable_subset;  // rank-revealing QR order
  std::vector<Advice> advice;
  double seconds = 0;

  std::string FullReport() const;
};

void AnalyzeIdentifiability(const ModalModel& model, const Dataset& dataset,
                            const IdentifiabilityOptions& options,
                            IdentifiabilityReport* report);

}  // namespace ringid

#endif  // RINGID_ESTIMATION_IDENTIFIABILITY_H_
