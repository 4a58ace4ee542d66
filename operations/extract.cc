#include "operations/extract.h"

#include <algorithm>

#include "estimation/fit.h"
#include "estimation/frf_start.h"
#include "estimation/problem.h"
#include "model/rigid_ring_model.h"

namespace ringid {

bool ExtractDataset(const std::string& path, const ExtractSettings& s, Extracted* out,
                    InputError* error) {
  Dataset d;
  LoadError load;
  if (!LoadDataset(path, &d, &load)) {
    *error = InputError::Of(load);
    return false;
  }
  return ExtractDataset(d, path, s, out, error);
}

bool ExtractDataset(const Dataset& d, const std::string& path, const ExtractSettings& s,
                    Extracted* out, InputError* error) {
  PlscfOptions plscf;
  plscf.max_order = s.max_model_order;
  std::string why;
  if (!plscf.IsValid(&why)) {
    *error = InputError::Option("--max_model_order: " + why);
    return false;
  }
  const auto refuse = [&](const std::string& field, const std::string& message) {
    *error = {path + ": " + field + ": " + message, path, field, message};
    return false;
  };
  if (std::none_of(d.conditions.begin(), d.conditions.end(),
                   [](const Condition& c) { return c.frf.has_value(); })) {
    return refuse("conditions", "no condition has an frf block (contract §9) to extract modes from");
  }
  std::vector<PlscfResult> fits;
  const std::vector<std::vector<internal::FrfMode>> found =
      internal::ModesInFrfs(d, plscf, &why, &fits);
  if (found.empty()) {
    return refuse("conditions", why.empty() ? "the FRFs hold no stable physical pole" : why);
  }
  const RigidRingModel model;
  Status status;
  const auto problem = Problem::Create(model, d, ResidualOptions{}, &status);
  if (!problem) {
    *error = {path + ": " + status.message, path, "", status.message};
    return false;
  }
  const auto frf_cost = [&](const Eigen::VectorXd& x) {
    return internal::CostAt(problem->residuals(), x);
  };
  *out = Extracted{};
  if (!internal::FrfModalStart(model, d, problem->setup(), found, problem->start(), frf_cost,
                               &out->dataset)) {
    return refuse("conditions", "the extracted modes could not be labelled: the model at the "
                                "initial values pairs none of them, or its fit failed");
  }
  // Modes carry no modal mass: the masses and inertias are held where they are.
  std::vector<std::string> held;
  for (int i = 0; i < kNumParams; ++i) {
    const Param p = ParamAt(i);
    const auto it = d.initial.find(p);
    if (!IsMassOrInertia(p) || it == d.initial.end()) continue;
    out->dataset.initial.erase(p);
    out->dataset.known[p] = it->second;
    held.push_back(ParamName(p));
  }
  if (!held.empty()) {
    std::string list;
    for (const std::string& h : held) list += (list.empty() ? "" : ", ") + h;
    out->notes.push_back(list + " known at their initial values: modes carry no modal mass "
                         "(weigh them, or identify on the FRFs, which do)");
  }
  out->notes.push_back("frequencies and damping ratios without a sigma: identify weighs them by "
                       "its default relative errors");
  out->dataset.name = d.name + " (modes extracted)";
  for (size_t c = 0; c < found.size(); ++c) {
    for (const internal::FrfMode& f : found[c]) {
      ExtractedPole pole{static_cast<int>(c), f.frequency_hz, f.damping_ratio, f.stable_orders};
      for (const MeasuredMode& m : out->dataset.modes) {
        if (m.condition == static_cast<int>(c) && m.frequency_hz == f.frequency_hz) {
          pole.label = m.label;
          pole.shape = !m.shape.empty();
        }
      }
      out->poles.push_back(pole);
    }
  }
  for (size_t c = 0; c < fits.size(); ++c) {
    if (!d.conditions[c].frf) continue;
    out->conditions.push_back({static_cast<int>(c), *d.conditions[c].frf, std::move(fits[c])});
  }
  return true;
}

}  // namespace ringid
