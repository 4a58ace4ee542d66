#include "estimation/frf_start.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <utility>

#include <Eigen/QR>

#include "datasets/pairing.h"
#include "estimation/identify.h"
#include "estimation/plscf.h"
#include "estimation/setup.h"
#include "model/frequency_response.h"

namespace ringid {
namespace internal {
namespace {

// The pole of a damped frequency and damping ratio: lambda = -zeta wn + i wd.
Complex Pole(const FrfMode& m) {
  const double wd = 2 * M_PI * m.frequency_hz;
  const double zeta = std::clamp(m.damping_ratio, -0.999, 0.999);
  const double wn = wd / std::sqrt(1 - zeta * zeta);
  return {-zeta * wn, wd};
}

int Order(FrfQuantity q) { return static_cast<int>(q); }  // displacement 0, velocity 1, ...

// The physical poles of `frf` with their shapes on the outputs (pLSCF and
// LSFD at their defaults), the extraction in `r`; none where it fails.
std::vector<FrfMode> ExtractFrfModes(const Frf& frf, const PlscfOptions& o, std::string* why,
                                     PlscfResult* r) {
  ExtractModes(frf, o, r);
  std::vector<FrfMode> out;
  if (!r->status.ok()) {
    if (why && why->empty()) *why = r->status.message;
    return out;
  }
  for (const ExtractedMode& m : r->modes) {
    if (m.shape.size() != static_cast<int>(frf.outputs.size())) continue;
    out.push_back({m.frequency_hz, m.damping_ratio, m.shape, m.stable_orders, m.frequency_std_hz,
                   m.damping_ratio_std});
  }
  return out;
}


// The outputs' combinations (contract §9) over the coordinates they touch
// that `model` has (`columns`); false where an output is an axle channel.
bool OutputMatrix(const ModalModel& model, const Frf& frf, std::vector<Dof>* columns,
                  Eigen::MatrixXd* C) {
  columns->clear();
  for (const FrfOutput& out : frf.outputs) {
    if (out.channel) return false;
    for (const auto& [dof, c] : out.coordinates) {
      if (std::find(columns->begin(), columns->end(), dof) == columns->end() &&
          !MissingCoordinate(model, {{dof, 1.0}})) {
        columns->push_back(dof);
      }
    }
  }
  *C = Eigen::MatrixXd::Zero(frf.outputs.size(), columns->size());
  for (size_t o = 0; o < frf.outputs.size(); ++o) {
    for (size_t j = 0; j < columns->size(); ++j) {
      const auto it = frf.outputs[o].coordinates.find((*columns)[j]);
      if (it != frf.outputs[o].coordinates.end()) (*C)(o, j) = it->second;
    }
  }
  return !columns->empty();
}

// The mode's outputs as displacements: a velocity or acceleration output
// divided by the pole's power (§9: a factor (iω)^order).
Eigen::VectorXcd Displacements(const Frf& frf, const FrfMode& mode) {
  const Complex lambda = Pole(mode);
  Eigen::VectorXcd r = mode.outputs;
  for (int o = 0; o < r.size(); ++o) r[o] /= std::pow(lambda, Order(frf.outputs[o].quantity));
  return r;
}

// The complex MAC of a measured and a model shape on the outputs.
double OutputMac(const Eigen::VectorXcd& measured, const Eigen::VectorXcd& model) {
  const double den = measured.squaredNorm() * model.squaredNorm();
  return den > 0 ? std::norm(measured.dot(model)) / den : 0;
}

// The one-to-one assignment of `mac` rows (measured) to columns (model
// modes) with the largest sum, by exhaustive search (at most 7 of 7).
void BestAssignment(const Eigen::MatrixXd& mac, int row, std::vector<bool>* used,
                    std::vector<int>* pick, double sum, double* best_sum, std::vector<int>* best) {
  if (row == mac.rows()) {
    if (sum > *best_sum) {
      *best_sum = sum;
      *best = *pick;
    }
    return;
  }
  for (int j = 0; j < mac.cols(); ++j) {
    if ((*used)[j]) continue;
    (*used)[j] = true;
    (*pick)[row] = j;
    BestAssignment(mac, row + 1, used, pick, sum + mac(row, j), best_sum, best);
    (*used)[j] = false;
  }
}

// `at`'s values of `setup`'s free parameters, in its coordinates.
Eigen::VectorXd InSetup(const ParameterSetup& setup, const std::vector<Parameters>& at,
                        const Eigen::VectorXd& from) {
  Eigen::VectorXd x = from;
  for (int i = 0; i < setup.size(); ++i) {
    x[i] = setup.ToCoordinate(i, at[std::max(setup.condition_of(i), 0)][setup.free()[i]]);
  }
  return x;
}

// The modal stage's fits: `starts` starts on one thread, the fit alone.
IdentifyOptions StageOptions(int starts) {
  IdentifyOptions o;
  o.starts = starts;
  o.threads = 1;
  o.analysis = false;
  return o;
}

}  // namespace

std::vector<std::pair<Dof, double>> ShapeOnCoordinates(const ModalModel& model, const Frf& frf,
                                                      const FrfMode& mode) {
  std::vector<Dof> columns;
  Eigen::MatrixXd C;
  if (!OutputMatrix(model, frf, &columns, &C) || mode.outputs.size() != C.rows()) return {};
  const Eigen::VectorXcd r = Displacements(frf, mode);
  // The coordinates the outputs determine: those whose unit vector lies in
  // C's row space. The shape is theirs where they carry the mode's outputs.
  const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(C);
  const Eigen::MatrixXd projector = cod.pseudoInverse() * C;  // onto the row space
  std::vector<int> determined;
  for (int j = 0; j < C.cols(); ++j) {
    if ((projector.col(j) - Eigen::VectorXd::Unit(C.cols(), j)).norm() < 1e-9) determined.push_back(j);
  }
  if (determined.empty()) return {};
  Eigen::MatrixXd Cd(C.rows(), determined.size());
  for (size_t k = 0; k < determined.size(); ++k) Cd.col(k) = C.col(determined[k]);
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(Cd);
  const Eigen::VectorXcd v = qr.solve(r.real()) + Complex(0, 1) * qr.solve(r.imag());
  const Eigen::VectorXcd fitted = Cd.cast<Complex>() * v;
  if ((fitted - r).squaredNorm() > kUndeterminedShare * r.squaredNorm()) return {};
  int big = 0;
  for (int k = 1; k < v.size(); ++k) {
    if (std::norm(v[k]) > std::norm(v[big])) big = k;
  }
  if (!(std::abs(v[big]) > 0)) return {};
  const Complex turn = std::conj(v[big]) / std::norm(v[big]);  // largest real, scaled to 1 (§2)
  std::vector<std::pair<Dof, double>> shape;
  for (size_t k = 0; k < determined.size(); ++k) {
    shape.push_back({columns[determined[k]], std::real(turn * v[k])});
  }
  return shape;
}

std::vector<ModeLabel> LabelsOnOutputs(const ModalModel& model, const Frf& frf,
                                       const std::vector<FrfMode>& found,
                                       const ModalSolution& at) {
  std::vector<Dof> columns;
  Eigen::MatrixXd C;
  if (!OutputMatrix(model, frf, &columns, &C) || found.size() > at.modes.size()) return {};
  Eigen::MatrixXd mac(found.size(), at.modes.size());
  for (size_t m = 0; m < found.size(); ++m) {
    if (found[m].outputs.size() != C.rows()) return {};
    const Eigen::VectorXcd r = Displacements(frf, found[m]);
    for (size_t j = 0; j < at.modes.size(); ++j) {
      Eigen::VectorXcd shape(columns.size());
      for (size_t k = 0; k < columns.size(); ++k) {
        shape[k] = at.modes[j].shape[static_cast<int>(columns[k])];
      }
      mac(m, j) = OutputMac(r, C.cast<Complex>() * shape);
    }
  }
  std::vector<bool> used(at.modes.size(), false);
  std::vector<int> pick(found.size()), best;
  double best_sum = -1;
  BestAssignment(mac, 0, &used, &pick, 0, &best_sum, &best);
  std::vector<ModeLabel> labels;
  for (int j : best) labels.push_back(at.modes[j].label);
  return labels;
}

bool ModalStageDataset(const ModalModel& model, const Dataset& d,
                       const std::vector<std::vector<FrfMode>>& found,
                       const std::vector<Parameters>& at, Dataset* out, std::string* why) {
  *out = d;
  std::vector<bool> has_modes(d.conditions.size(), false);
  for (const MeasuredMode& m : d.modes) has_modes[m.condition] = true;
  int added = 0;
  for (size_t c = 0; c < d.conditions.size(); ++c) {
    std::optional<Frf> frf;
    std::swap(frf, out->conditions[c].frf);
    if (!frf || has_modes[c] || c >= found.size() || c >= at.size()) continue;
    const ModalSolution s = model.Solve(at[c], d.conditions[c].speed_m_s);
    if (!s.ok) continue;
    // At most as many as the model has: the strongest (largest on the
    // outputs per unit damping) first.
    std::vector<FrfMode> kept = found[c];
    std::stable_sort(kept.begin(), kept.end(), [](const FrfMode& a, const FrfMode& b) {
      return a.outputs.norm() / std::max(a.damping_ratio, 1e-3) >
             b.outputs.norm() / std::max(b.damping_ratio, 1e-3);
    });
    kept.resize(std::min(kept.size(), s.modes.size()));
    std::vector<MeasuredMode> modes;
    for (const FrfMode& f : kept) {
      MeasuredMode m;
      m.frequency_hz = f.frequency_hz;
      m.damping_ratio = f.damping_ratio;
      if (f.frequency_std_hz > 0) m.frequency_sigma_hz = f.frequency_std_hz;  // NaN: none
      if (f.damping_ratio_std > 0) m.damping_sigma = f.damping_ratio_std;
      m.shape = ShapeOnCoordinates(model, *frf, f);
      m.condition = static_cast<int>(c);
      modes.push_back(std::move(m));
    }
    std::vector<ModeLabel> labels = LabelsOnOutputs(model, *frf, kept, s);
    if (labels.empty()) {  // axle channels: by frequency (datasets/pairing.h)
      std::vector<ModeToPair> measured;
      for (const MeasuredMode& m : modes) measured.push_back({m.frequency_hz, &m.shape, std::nullopt});
      std::vector<const Mode*> model_modes;
      for (const Mode& m : s.modes) model_modes.push_back(&m);
      std::vector<int> pick;
      std::vector<PairedBy> by;
      std::string unpaired;
      if (!PairModes(measured, model_modes, ShapeConvention::kContract, &pick, &by, &unpaired)) continue;
      for (int j : pick) labels.push_back(model_modes[j]->label);
    }
    for (size_t r = 0; r < modes.size(); ++r) {
      modes[r].label = labels[r];
      out->modes.push_back(modes[r]);
      ++added;
    }
  }
  if (added == 0) {
    *why = "the FRFs gave no mode the model could pair";
    return false;
  }
  if (d.statics.empty()) {  // modes carry no scale: hold one mass
    for (int i = 0; i < kNumParams; ++i) {
      const Param p = ParamAt(i);
      if (IsMassOrInertia(p) && out->initial.count(p)) {
        out->known[p] = out->initial[p];
        out->initial.erase(p);
        break;
      }
    }
  }
  return true;
}

std::vector<std::vector<FrfMode>> ModesInFrfs(const Dataset& d, const PlscfOptions& o,
                                             std::string* why,
                                             std::vector<PlscfResult>* results) {
  std::vector<std::vector<FrfMode>> found(d.conditions.size());
  std::vector<PlscfResult> r(d.conditions.size());
  bool any = false;
  for (size_t c = 0; c < d.conditions.size(); ++c) {
    if (!d.conditions[c].frf) continue;
    found[c] = ExtractFrfModes(*d.conditions[c].frf, o, why, &r[c]);
    any = any || !found[c].empty();
  }
  if (!any) found.clear();
  if (results) *results = std::move(r);
  return found;
}

std::vector<std::vector<FrfMode>> StageModes(const Dataset& d) {
  PlscfOptions o;
  o.refine = false;
  std::vector<std::vector<FrfMode>> found(d.conditions.size());
  bool any = false;
  for (size_t c = 0; c < d.conditions.size(); ++c) {
    const std::optional<Frf>& frf = d.conditions[c].frf;
    if (!frf || std::any_of(frf->outputs.begin(), frf->outputs.end(),
                            [](const FrfOutput& out) { return out.channel.has_value(); })) {
      continue;
    }
    PlscfResult r;
    found[c] = ExtractFrfModes(*frf, o, nullptr, &r);
    any = any || !found[c].empty();
  }
  if (!any) found.clear();
  return found;
}

std::optional<Eigen::VectorXd> FrfModalStart(const ModalModel& model, const Dataset& d,
                                             const ParameterSetup& setup,
                                             const std::vector<std::vector<FrfMode>>& found,
                                             const Eigen::VectorXd& from, Dataset* stage) {
  if (found.empty()) return std::nullopt;
  Dataset start = d;  // the FRF dataset's initial values at `from`
  std::vector<Parameters> at;
  for (int c = 0; c < static_cast<int>(d.conditions.size()); ++c) at.push_back(setup.Decode(from.data(), c));
  for (auto& [q, v] : start.initial) v = at[0][q];
  const IdentifyOptions o = StageOptions(kModalStageStarts);
  // Labelled by the model at `from`, fitted, and labelled again at the fit
  // until no label changes (at most kLabelRounds rounds).
  Dataset modal;
  IdentifyResult r;
  bool fitted_once = false;
  std::string why;
  for (int round = 0; round < kLabelRounds; ++round) {
    Dataset next;
    if (!ModalStageDataset(model, start, found, at, &next, &why)) break;
    bool same = round > 0 && next.modes.size() == modal.modes.size();
    for (size_t k = 0; same && k < next.modes.size(); ++k) same = next.modes[k].label == modal.modes[k].label;
    if (same) break;
    modal = std::move(next);
    Identify(model, modal, o, &r);
    if (!r.status.ok()) return std::nullopt;
    fitted_once = true;
    ParameterSetup fitted;
    if (!ParameterSetup::Build(model, modal, &fitted, &why)) return std::nullopt;
    for (size_t c = 0; c < at.size(); ++c) at[c] = fitted.Decode(r.x.data(), static_cast<int>(c));
  }
  if (!fitted_once) return std::nullopt;
  if (stage) *stage = std::move(modal);
  return InSetup(setup, at, from);
}

std::optional<Eigen::VectorXd> OtherLabelOrderStart(
    const ModalModel& model, const ParameterSetup& setup, const Dataset& stage,
    const Eigen::VectorXd& from, const std::function<double(const Eigen::VectorXd&)>& frf_cost) {
  std::vector<size_t> shapeless;
  for (size_t k = 0; k < stage.modes.size(); ++k) {
    if (stage.modes[k].shape.empty()) shapeless.push_back(k);
  }
  if (shapeless.size() < 2 || shapeless.size() > kMaxPermutedLabels) return std::nullopt;
  std::vector<ModeLabel> labels;
  for (size_t k : shapeless) labels.push_back(stage.modes[k].label);
  const std::vector<ModeLabel> first = labels;
  std::sort(labels.begin(), labels.end());
  const IdentifyOptions o = StageOptions(1);  // from `from`: the labels, not the start, are on trial
  std::optional<Eigen::VectorXd> best;
  double best_cost = std::numeric_limits<double>::infinity();
  std::string why;
  do {
    if (labels == first) continue;
    Dataset other = stage;
    for (size_t k = 0; k < shapeless.size(); ++k) other.modes[shapeless[k]].label = labels[k];
    IdentifyResult r;
    Identify(model, other, o, &r);
    ParameterSetup fitted;
    if (!r.status.ok() || !ParameterSetup::Build(model, other, &fitted, &why)) continue;
    std::vector<Parameters> there;
    for (int c = 0; c < static_cast<int>(stage.conditions.size()); ++c) {
      there.push_back(fitted.Decode(r.x.data(), c));
    }
    const Eigen::VectorXd x = InSetup(setup, there, from);
    if (const double cost = frf_cost(x); cost < best_cost) {
      best_cost = cost;
      best = x;
    }
  } while (std::next_permutation(labels.begin(), labels.end()));
  return best;
}

}  // namespace internal
}  // namespace ringid
