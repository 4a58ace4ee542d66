// The sim-to-real gap: where the calibrated baseline misses the test, which
// unmodelled effect of the catalogue explains it, and how far it shrinks.
#ifndef RINGID_ESTIMATION_DIAGNOSE_H_
#define RINGID_ESTIMATION_DIAGNOSE_H_

#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "estimation/identify.h"

namespace ringid {

struct DiagnoseOptions {
  IdentifyOptions fit;  // multi-start settings for every calibration
  // The baseline's chi-square p-value below which the gap is significant.
  double gap_significance = 0.01;
  // An effect is supported when its likelihood-ratio p-value is below this
  // (six candidates: a Bonferroni-safe level) and it lowers the AIC, whether
  // or not the omnibus gap test is significant. The verdict's group is
  // decided at the same level, by a likelihood-ratio threshold: a fitted
  // effect whose chi-square differs from the verdict's by less than the
  // chi-square significant at this level, on as many degrees of freedom as
  // their numbers of parameters differ (at least one), cannot be told apart
  // from it on these data.
  double effect_significance = 1e-3;
  // Only the effects whose score test at the baseline's optimum (the pull of
  // the data on their size at 0, estimation/score.h) has a p-value below
  // this are refitted, with their rivals: the effects whose signatures
  // overlap theirs (canonical correlation above kRivalOverlap) and any whose
  // score comes within the verdict's group threshold. The others keep their
  // score and detectable sizes. An effect without a derivative at size 0 (the
  // hub) is always refitted. 1 refits every effect, as does a baseline
  // that misses by far more than the noise (kScreenReducedChiSquare).
  double screen_significance = 0.05;
  // An effect too small to name is stated with the smallest size whose
  // signature a re-calibration of the baseline cannot absorb: the size at
  // which the likelihood ratio against the re-calibrated baseline reaches this.
  double detectable_likelihood_ratio = 20.0;
  // A baseline parameter that the verdict's fit moves beyond this factor had
  // absorbed part of the gap.
  double absorbed_factor = 2.0;
  // Leave-one-mode-out prediction for the baseline and every supported
  // effect: each mode predicted from a fit without it. Reported, not voted
  // on: a dropped mode frees directions only it determined, so the absolute
  // held-out chi-square is large (1e5 for a calibrated baseline seen); the
  // shrink from baseline to effect is what to read.
  bool held_out = true;
  // Called as the diagnosis goes: steps done of total (the baseline, each
  // candidate effect, the verdict; a re-calibration adds its own), from any
  // of its threads, one call at a time.
  std::function<void(int done, int total)> on_step;
  bool IsValid(std::string* why) const;
};

inline constexpr double kNotAvailable = std::numeric_limits<double>::quiet_NaN();

// Two effects whose score signatures share a direction this closely (the
// largest canonical correlation of their parts outside the baseline's span)
// are rivals: one may fit what the other's score shows.
inline constexpr double kRivalOverlap = 0.5;
// The screen applies where the calibrated baseline's chi-square per degree of
// freedom is at most this: where it misses by more, an effect's pull at size
// 0 says little of what it does at its size (seen: a lug coupling that closes
// a chi-square of 2892 on 63 degrees of freedom, and an axle torsion whose
// mode crosses the band's first lines, each scored 0 at the baseline).
inline constexpr double kScreenReducedChiSquare = 2.0;

struct EffectFit {
  const Effect* effect = nullptr;
  bool ok = false;
  std::string note;                      // why not, when !ok
  int extra_parameters = 0;
  // The score test at the baseline's optimum (estimation/score.h); NaN
  // where the effect's model could not be evaluated there.
  double score_statistic = kNotAvailable, score_p = kNotAvailable;
  int score_dof = 0;
  // NaN (null in reports) for an effect that was not fitted.
  double chi2 = kNotAvailable;                         // 2 x cost
  double lrt_statistic = kNotAvailable, lrt_p = kNotAvailable;  // against the baseline
  // The likelihood ratio significant at the report's level on
  // extra_parameters degrees of freedom (the chi-square quantile).
  double lrt_threshold = kNotAvailable;
  double aic = kNotAvailable, bic = kNotAvailable;
  double gap_after = kNotAvailable;                    // chi2 in excess of its dof
  double shrink = kNotAvailable;                       // 1 - gap_after / gap_before
  bool supported = false;
  std::map<std::string, double> values;  // fitted effect parameters
  std::vector<double> mode_chi2;         // per measured mode
  std::vector<ModeMisfit> where;         // per measured mode, at this fit
  std::optional<double> held_out_chi2;   // leave-one-mode-out prediction
  // Per effect parameter: the smallest |value| whose signature a
  // re-calibration of the baseline cannot absorb (likelihood ratio 20).
  std::map<std::string, double> minimal_detectable;
  // Per effect parameter that free baseline parameters absorb whatever its
  // size (a structural invariance, at the effect's fit or for a screened
  // effect at its typical sizes, that the data's
  // Jacobian confirms: a sensor mass on FRFs and free m_b, I_by, I_bx,
  // I_bz), those parameters (internal::AbsorbedBy); such a parameter has no
  // minimal_detectable. An effect whose every sizing parameter is absorbed
  // (AbsorbedWhole) is never supported: these data cannot show it.
  std::map<std::string, std::vector<std::string>> absorbed_by;
  // Against the verdict's effect (NaN where there is none): this fit's
  // chi-square minus the verdict's, and the chi-square significant at the
  // report's level on max(|difference in parameters|, 1) degrees of freedom.
  // Below it in magnitude the two are one group.
  double chi2_above_verdict = kNotAvailable;
  double group_threshold = kNotAvailable;

  bool AbsorbedWhole() const;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("effect", &effect);
    a->Visit("fitted", &ok);
    a->Visit("note", &note);
    a->Visit("gap_after", &gap_after);
    a->Visit("shrink", &shrink);
    a->Visit("supported", &supported);
    a->Visit("values", &values);
    a->Visit("minimal_detectable", &minimal_detectable);
    a->Visit("absorbed_by", &absorbed_by);
    a->Visit("where", &where);
    a->Group("evidence", [&](auto* g) {
      g->Visit("score_statistic", &score_statistic);
      g->Visit("score_dof", &score_dof);
      g->Visit("score_p_value", &score_p);
      g->Visit("chi2", &chi2);
      g->Visit("likelihood_ratio", &lrt_statistic);
      g->Visit("extra_parameters", &extra_parameters);
      g->Visit("lrt_p_value", &lrt_p);
      g->Visit("likelihood_ratio_threshold", &lrt_threshold);
      g->Visit("aic", &aic);
      g->Visit("bic", &bic);
      g->Visit("held_out_chi2", &held_out_chi2);
      g->Visit("mode_chi2", &mode_chi2);
      g->Visit("chi2_above_verdict", &chi2_above_verdict);
      g->Visit("group_threshold", &group_threshold);
    });
  }
};

struct DiagnosisResult {
  Status status;
  // The gap: the calibrated baseline.
  IdentifyResult baseline;
  double chi2_before = 0;
  int dof = 0;
  std::optional<double> p_value;  // none when no degree of freedom is left
  bool significant = false;
  double gap_before = 0;          // chi2 in excess of its dof
  // Where it lies: per measured mode, and per other measurement where any.
  std::vector<ModeMisfit> where;
  std::optional<std::vector<ItemMisfit>> where_else;
  // Baseline parameters that had absorbed part of the gap: moved beyond
  // absorbed_factor by the verdict's fit, or beyond kPriorConflictZ of a
  // declared prior where there is no verdict.
  std::vector<std::string> absorbed;
  std::optional<double> held_out_before;
  // Which effect: the fitted ranked by AIC, then those the score test
  // screened out (fitted false) by its p-value.
  std::vector<EffectFit> ranking;
  const Effect* verdict = nullptr;  // none
  std::vector<const Effect*> indistinguishable;
  // The significance level of the effects' likelihood-ratio tests and of the
  // group (each effect's group_threshold is the chi-square point at it).
  double level = kNotAvailable;
  std::string explanation;
  std::vector<double> mode_shrink;  // per measured mode, for the verdict
  double seconds = 0;

  std::string FullReport() const;

  template <class Archive>
  void Serialize(Archive* a) {
    status.Serialize(a);
    a->Group("gap_before", [&](auto* g) {
      g->Visit("chi2", &chi2_before);
      g->Visit("dof", &dof);
      g->Visit("p_value", &p_value);
      g->Visit("significant", &significant);
      g->Visit("excess", &gap_before);
    });
    a->Visit("where", &where);
    a->VisitIfSet("where_else", &where_else);
    a->Visit("mode_shrink", &mode_shrink);
    a->Visit("absorbed", &absorbed);
    a->Visit("ranking", &ranking);
    a->Visit("held_out_before", &held_out_before);
    a->Group("verdict", [&](auto* g) {
      g->Visit("effect", &verdict);
      g->Visit("indistinguishable", &indistinguishable);
      g->Visit("level", &level);
      g->Visit("explanation", &explanation);
    });
    a->Visit("seconds", &seconds);
  }
};

// `baseline`: the model calibrated first (usually RigidRingModel(), the
// standing model) by the multistart of Identify, with no prior but the
// dataset's own; each effect of the catalogue it lacks is then scored at the
// baseline's optimum (estimation/score.h), and those the score keeps
// (screen_significance) and their rivals are fitted on top, from the
// baseline's optimum with the effect at 0 and at the best of a scan of sizes.
// Nothing depends on the dataset's initial values beyond the baseline's
// starts.
void Diagnose(const RigidRingModel& baseline, const Dataset& dataset,
              const DiagnoseOptions& options, DiagnosisResult* report);

}  // namespace ringid

#endif  // RINGID_ESTIMATION_DIAGNOSE_H_
