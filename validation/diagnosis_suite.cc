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
bool AbsorbedAsStated(const DiagnosisResult& r, const Effect& effect, double value) {
  for (const EffectFit& f : r.ranking) {
    if (f.effect != &effect) continue;
    const auto mde = f.minimal_detectable.find(ParamName(effect.size()));
    return mde != f.minimal_detectable.end() && std::abs(value) < mde->second;
  }
  return false;
}

}  // namespace

namespace {

// The dataset of one case: `truth` measured standing (speeds {0}) or
// standing and on the drum, with the engineer's knowns and ties and the truth
// as initial values.
Status CaseData(const Effect* effect, const Parameters& truth, const std::vector<double>& speeds,
                std::mt19937_64* rng, Dataset* d) {
  if (speeds.size() > 1) {
    d->format = 2;
    for (double v : speeds) {
      Condition c;
      c.name = ConditionName(v);
      c.speed_m_s = v;
      d->conditions.push_back(c);
    }
  }
  SetEngineerPriors(truth, 0, rng, d);
  std::vector<const Effect*> withheld;
  if (effect) withheld.push_back(effect);
  std::string why;
  if (!Simulate(RigidRingModel(withheld), truth, SimulateOptions{}, rng, d, &why)) {
    return Status::Failed(d->name + ": " + why);
  }
  return Status::Success();
}

}  // namespace

Status RunDiagnosisSuite(const SuiteOptions& o, DiagnosisSuite* suite) {
  if (!(o.start_factor >= 1) || !std::isfinite(o.start_factor)) {
    return Status::InvalidInput("start_factor: must be finite and at least 1");
  }
  Dataset table1;
  Parameters paper;
  if (Status s = LoadPaper(o, &table1, &paper); !s.ok()) return s;
  // nullptr: no effect withheld.
  std::vector<const Effect*> truths = {nullptr};
  for (const Effect* e : EffectCatalogue()) truths.push_back(e);
  suite->effects = EffectNames(truths);
  suite->start_factor = o.start_factor;
  const double scales[] = {0.8, 1.0, 1.25};
  // Per truth: standing (the paper's tire) and rolling (the car tire) in
  // turn, each at two effect sizes and three tire sizes.
  const int per_truth = std::clamp(o.replicates, 1, 10);
  const int total = static_cast<int>(truths.size()) * per_truth;
  std::mt19937_64 rng(o.seed);
  std::uniform_real_distribution<double> scatter(-std::log(o.start_factor), std::log(o.start_factor));
  int correct = 0, shrink_n = 0;
  double shrink_sum = 0, seconds = 0;
  for (const Effect* effect : truths) {
    const std::string truth_name = EffectName(effect);
    for (int k = 0; k < per_truth; ++k) {
      const bool rolling = k % 2 == 1;
      const double scale = scales[(k / 2) % 3];
      const double shift = effect ? (k / 2 % 2 ? 0.05 : 0.03) : 0;
      Parameters truth = ScaledTire(rolling ? ExampleCarTire() : paper, scale);
      truth[Param::m_a] = 15 * scale * scale;
      DiagnosisCase c;
      c.truth = truth_name;
      c.shift = shift;
      c.speeds_m_s = rolling ? o.speeds : std::vector<double>{0};
      if (effect) c.value = truth[effect->size()] = ValueForShift(truth, *effect, effect->size(), shift);
      Dataset exact;
      exact.name = c.name = truth_name + "-" + std::to_string(suite->cases.size());
      if (Status s = CaseData(effect, truth, c.speeds_m_s, &rng, &exact); !s.ok()) return s;
      Dataset d = exact;
      for (auto& [param, value] : d.initial) value *= std::exp(scatter(rng));
      DiagnoseOptions dopt;
      dopt.held_out = false;  // reported by diagnose, not voted on; skipped for speed
      dopt.fit.residuals.derivatives = o.derivatives;
      DiagnosisResult dr, from_truth;
      Diagnose(RigidRingModel(), d, dopt, &dr);
      if (!dr.status.ok()) return Status::Failed(d.name + ": " + dr.status.message);
      Diagnose(RigidRingModel(), exact, dopt, &from_truth);
      if (!from_truth.status.ok()) return Status::Failed(d.name + ": " + from_truth.status.message);
      seconds += dr.seconds;
      c.verdict = EffectName(dr.verdict);
      c.indistinguishable = EffectNames(dr.indistinguishable);
      c.verdict_from_truth = EffectName(from_truth.verdict);
      c.indistinguishable_from_truth = EffectNames(from_truth.indistinguishable);
      c.same_as_from_truth = c.verdict == c.verdict_from_truth &&
                             c.indistinguishable == c.indistinguishable_from_truth;
      suite->differ_from_truth_start += !c.same_as_from_truth;
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
      suite->wrong += !c.correct;
      ++suite->confusion[truth_name][EffectName(dr.verdict)];
      suite->cases.push_back(std::move(c));
      if (o.on_case) o.on_case(static_cast<int>(suite->cases.size()), total);
    }
  }
  const double n = static_cast<double>(suite->cases.size());
  suite->accuracy = correct / n;
  suite->mean_shrink_when_named = shrink_n ? shrink_sum / shrink_n : 0.0;
  suite->seconds_per_diagnosis = seconds / n;
  return Status::Success();
}

}  // namespace ringid
