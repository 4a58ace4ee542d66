#include "estimation/extract.h"

#include <algorithm>
#include <cstdio>

#include "datasets/pairing.h"
#include "estimation/frf_start.h"
#include "estimation/identify.h"
#include "estimation/problem.h"
#include "estimation/setup.h"

namespace ringid {
namespace {

// The parameters both fits class yes, side by side.
std::vector<RouteRow> Routes(const IdentifyResult& direct, const IdentifyResult& modal) {
  std::vector<RouteRow> rows;
  for (const ParameterEstimate& a : direct.estimates) {
    if (!a.free || a.tied_to || a.identifiable != Identifiability::kYes || !a.std) continue;
    for (const ParameterEstimate& b : modal.estimates) {
      if (b.key.Text() != a.key.Text() || !b.free || b.identifiable != Identifiability::kYes || !b.std) {
        continue;
      }
      rows.push_back({a.key.Text(), a.value, *a.std, b.value, *b.std});
    }
  }
  return rows;
}

// The modes of `modal` relabelled by the model at the parameters `fit`
// found for d's FRFs (datasets/pairing.h: shapes by MAC, the rest by
// frequency). The modal stage's labels of modes without a shape are only a
// start's: near the optimum the model may name those modes otherwise.
bool RelabelAtFit(const ModalModel& model, const Dataset& d, const internal::ParameterSetup& setup,
                  const Eigen::VectorXd& fit, Dataset* modal) {
  for (int c = 0; c < static_cast<int>(d.conditions.size()); ++c) {
    // A condition with measured modes keeps them as measured (ModalStageDataset).
    if (std::any_of(d.modes.begin(), d.modes.end(), [&](const MeasuredMode& m) { return m.condition == c; })) {
      continue;
    }
    std::vector<MeasuredMode*> in;
    for (MeasuredMode& m : modal->modes) {
      if (m.condition == c) in.push_back(&m);
    }
    if (in.empty()) continue;
    const ModalSolution s = model.Solve(setup.Decode(fit.data(), c), d.conditions[c].speed_m_s);
    if (!s.ok) return false;
    std::vector<internal::ModeToPair> measured;
    // With their damping: at the fit both sides' poles are estimates of the
    // same poles, and modes a fraction of a hertz apart differ in damping.
    for (const MeasuredMode* m : in) {
      measured.push_back({m->frequency_hz, &m->shape, std::nullopt, m->damping_ratio});
    }
    std::vector<const Mode*> modes;
    for (const Mode& m : s.modes) modes.push_back(&m);
    std::vector<int> pick;
    std::vector<internal::PairedBy> by;
    std::string why;
    if (!internal::PairModes(measured, modes, ShapeConvention::kContract, &pick, &by, &why)) {
      return false;
    }
    for (size_t k = 0; k < in.size(); ++k) in[k]->label = modes[pick[k]]->label;
  }
  return true;
}

}  // namespace

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
  std::vector<PlscfResult> fits;
  const std::vector<std::vector<internal::FrfMode>> found =
      internal::ModesInFrfs(d, plscf, &why, &fits);
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
  // Named as the model names them at the fit to the FRFs (the direct route,
  // identify's default starts), where the FRFs fix every parameter: the
  // modal stage's names of modes without a shape are only a start's.
  IdentifyResult fit;
  Identify(*problem, IdentifyOptions{}, &fit);
  if (!fit.status.ok()) {
    r->status = Status::Failed("the fit to the FRFs that names the modes failed: " + fit.status.message);
    return;
  }
  std::vector<Parameters> at;
  for (int c = 0; c < static_cast<int>(d.conditions.size()); ++c) {
    at.push_back(problem->setup().Decode(fit.x.data(), c));
  }
  if (!internal::ModalStageDataset(model, d, found, at, &r->dataset, &why) ||
      !RelabelAtFit(model, d, problem->setup(), fit.x, &r->dataset)) {
    r->status = Status::Failed("the model at the fit to the FRFs pairs none of the extracted "
                               "modes" + (why.empty() ? std::string() : ": " + why));
    return;
  }
  char line[200];
  std::snprintf(line, sizeof line, "labelled by the model at the fit to the FRFs (chi-square "
                "%.6g on %d degrees of freedom)", fit.fit.chi_square, fit.fit.degrees_of_freedom);
  r->notes.push_back(line);
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
  bool sigmas = true;
  for (const MeasuredMode& m : r->dataset.modes) sigmas = sigmas && m.frequency_sigma_hz && m.damping_sigma;
  r->notes.push_back(sigmas ? "sigmas: the standard errors of the maximum-likelihood refinement "
                              "of the poles (estimation/modal_refine.h)"
                            : "a mode without sigma: the refinement failed or was off; identify "
                              "weighs it by its default relative errors");
  r->dataset.name = d.name + " (modes extracted)";
  for (size_t c = 0; c < found.size(); ++c) {
    for (const internal::FrfMode& f : found[c]) {
      ExtractedPole pole{static_cast<int>(c), f.frequency_hz, f.damping_ratio, f.stable_orders};
      if (f.frequency_std_hz > 0) pole.frequency_sigma_hz = f.frequency_std_hz;
      if (f.damping_ratio_std > 0) pole.damping_sigma = f.damping_ratio_std;
      for (const MeasuredMode& m : r->dataset.modes) {
        if (m.condition == static_cast<int>(c) && m.frequency_hz == f.frequency_hz) {
          pole.label = m.label;
          pole.shape = !m.shape.empty();
        }
      }
      r->poles.push_back(pole);
    }
  }
  for (size_t c = 0; c < fits.size(); ++c) {
    if (!d.conditions[c].frf) continue;
    r->conditions.push_back({static_cast<int>(c), *d.conditions[c].frf, std::move(fits[c])});
  }
  IdentifyResult modal;
  Identify(model, r->dataset, IdentifyOptions{}, &modal);
  if (modal.status.ok()) r->routes = Routes(fit, modal);
  r->status = Status::Success(std::to_string(r->dataset.modes.size()) + " modes");
}

}  // namespace ringid
