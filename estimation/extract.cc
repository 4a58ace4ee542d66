#include "estimation/extract.h"

#include <algorithm>

#include "estimation/fit.h"
#include "estimation/frf_start.h"
#include "estimation/problem.h"

namespace ringid {

void ExtractModalDataset(const ModalModel& model, const Dataset& d, const PlscfOptions& plscf,
                         ExtractResult* r) {
  *r = ExtractResult{};
  std::string why;
  if (!plscf.IsValid(&why)) {
    r->status = Status::InvalidInput(why);
    return;
  }
  if (std::none_of(d.conditions.begin(), d.conditions.end(),
                   [](const Condition& c) { return c.frf.has_value(); })) {
    r->status = Status::InvalidInput(
        "conditions: no condition has an frf block (contract §9) to extract modes from");
    return;
  }
  const std::vector<std::vector<internal::FrfMode>> found = internal::ModesInFrfs(d, plscf, &why);
  if (found.empty()) {
    r->status = Status::InvalidInput(
        "conditions: " + (why.empty() ? std::string("the FRFs hold no stable physical pole") : why));
    return;
  }
  Status status;
  const auto problem = Problem::Create(model, d, ResidualOptions{}, &status);
  if (!problem) {
    r->status = status;
    return;
  }
  const auto frf_cost = [&](const Eigen::VectorXd& x) {
    return internal::CostAt(problem->residuals(), x);
  };
  if (!internal::FrfModalStart(model, d, problem->setup(), found, problem->start(), frf_cost,
                               &r->dataset)) {
    r->status = Status::Failed("the extracted modes could not be labelled: the model at the "
                               "initial values pairs none of them, or its fit failed");
    return;
  }
  // Modes carry no modal mass: the masses and inertias are held where they are.
  std::string held;
  for (int i = 0; i < kNumParams; ++i) {
    const Param p = ParamAt(i);
    const auto it = d.initial.find(p);
    if (!IsMassOrInertia(p) || it == d.initial.end()) continue;
    r->dataset.initial.erase(p);
    r->dataset.known[p] = it->second;
    held += (held.empty() ? "" : ", ") + std::string(ParamName(p));
  }
  if (!held.empty()) {
    r->notes.push_back(held + " known at their initial values: modes carry no modal mass "
                       "(weigh them, or identify on the FRFs, which do)");
  }
  r->notes.push_back("frequencies and damping ratios without a sigma: identify weighs them by "
                     "its default relative errors");
  r->dataset.name = d.name + " (modes extracted)";
  for (size_t c = 0; c < found.size(); ++c) {
    for (const internal::FrfMode& f : found[c]) {
      ExtractedPole pole{static_cast<int>(c), f.frequency_hz, f.damping_ratio, f.stable_orders};
      for (const MeasuredMode& m : r->dataset.modes) {
        if (m.condition == static_cast<int>(c) && m.frequency_hz == f.frequency_hz) {
          pole.label = m.label;
          pole.shape = !m.shape.empty();
        }
      }
      r->poles.push_back(pole);
    }
  }
  r->status = Status::Success(std::to_string(r->dataset.modes.size()) + " modes");
}

}  // namespace ringid
