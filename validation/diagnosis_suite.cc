// The blind withheld-effect suite of the gap diagnosis (docs/conventions.md §5).
#include <algorithm>
#include <cmath>
#include <random>

#include "datasets/synthetic.h"
#include "estimation/diagnose.h"
#include "model/effects.h"
#include "model/rigid_ring_model.h"
#include "validation/suites.h"

namespace ringid {
namespace {

// Whether a "none" verdict on a case with `effect` at `value` is explained by
// the report's own minimal detectable size of that effect.
bool AbsorbedAsStated(const DiagnosisReport& r, const Effect& effect, double value) {
  for (const EffectFit& f : r.ranking) {
    if (f.effect != &effect) continue;
    const auto mde = f.minimal_detectable.find(ParamName(effect.size()));
    return mde != f.minimal_detectable.end() && std::abs(value) < mde->second;
  }
  return false;
}

}  // namespace

Status RunDiagnosisSuite(const SuiteOptions& o, DiagnosisSuite* suite) {
  Dataset table1;
  Parameters paper;
  if (Status s = LoadPaper(o, &table1, &paper); !s.ok()) return s;
  // nullptr: no effect withheld.
  std::vector<const Effect*> truths = {nullptr};
  for (const Effect* e : EffectCatalogue()) truths.push_back(e);
  suite->effects = EffectNames(truths);
  const double scales[] = {0.8, 1.0, 1.25};
  const int draws = std::clamp(o.replicates, 1, 3);
  const int total = static_cast<int>(truths.size()) * draws * 2;
  std::mt19937_64 rng(o.seed);
  int correct = 0, shrink_n = 0;
  double shrink_sum = 0, seconds = 0;
  for (const Effect* effect : truths) {
    const std::string truth_name = EffectName(effect);
    for (int k = 0; k < draws; ++k) {
      for (double shift : effect ? std::vector<double>{0.03, 0.05} : std::vector<double>{0, 0}) {
        Parameters truth = ScaledTire(paper, scales[k % 3]);
        truth[Param::m_a] = 15 * scales[k % 3] * scales[k % 3];
        std::vector<const Effect*> withheld;
        DiagnosisCase c;
        c.truth = truth_name;
        c.shift = shift;
        if (effect) {
          withheld.push_back(effect);
          c.value = truth[effect->size()] = ValueForShift(truth, *effect, effect->size(), shift);
        }
        Dataset d;
        d.name = c.name = truth_name + "-" + std::to_string(suite->cases.size());
        SetEngineerPriors(truth, 0.1, &rng, &d);
        std::string why;
        if (!Simulate(RigidRingModel(withheld), truth, SimulateOptions{}, &rng, &d, &why)) {
          return Status::Failed(d.name + ": " + why);
        }
        DiagnosisReport dr;
        DiagnoseOptions dopt;
        dopt.held_out = false;  // reported by diagnose, not voted on; skipped for speed
        dopt.fit.residuals.derivatives = o.derivatives;
        Diagnose(RigidRingModel(), d, dopt, &dr);
        if (!dr.status.ok()) return Status::Failed(d.name + ": " + dr.status.message);
        seconds += dr.seconds;
        c.verdict = EffectName(dr.verdict);
        c.indistinguishable = EffectNames(dr.indistinguishable);
        c.gap_p_value = dr.p_value;
        c.seconds = dr.seconds;
        const bool named =
            dr.verdict == effect ||
            std::count(dr.indistinguishable.begin(), dr.indistinguishable.end(), effect) > 0;
        c.absorbed_explained = effect && !dr.verdict && AbsorbedAsStated(dr, *effect, c.value);
        c.correct = named || c.absorbed_explained;
        suite->named += effect && named;
        suite->absorbed_and_explained += c.absorbed_explained;
        if (!effect) {
          ++suite->no_effect_cases;
          suite->false_alarms += dr.verdict != nullptr;
        } else if (named) {
          for (const EffectFit& f : dr.ranking) {
            if (f.effect != dr.verdict) continue;
            shrink_sum += f.shrink;
            ++shrink_n;
          }
        }
        correct += c.correct;
        ++suite->confusion[truth_name][EffectName(dr.verdict)];
        suite->cases.push_back(std::move(c));
        if (o.on_case) o.on_case(static_cast<int>(suite->cases.size()), total);
      }
    }
  }
  const double n = static_cast<double>(suite->cases.size());
  suite->accuracy = correct / n;
  suite->mean_shrink_when_named = shrink_n ? shrink_sum / shrink_n : 0.0;
  suite->seconds_per_diagnosis = seconds / n;
  return Status::Success();
}

}  // namespace ringid
