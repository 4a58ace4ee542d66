// The refinement's changes to the set of physical poles (estimation/plscf.h):
// poles added where the refined model misses the FRFs, and, where asked,
// dropped where the data do not call for them.
#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "estimation/plscf_internal.h"
#include "estimation/statistics.h"

namespace ringid::plscf_internal {
namespace {

using Complex = std::complex<double>;

// The physical poles whose damping has not settled across orders (a
// lightly damped mode's climbs slowly with the order): clusters of poles
// stable in frequency and vector, damping within kLooseDamping of the
// centre, none within stable_frequency of a pole in `modes`.
constexpr double kLooseDamping = 0.5;
std::vector<ExtractedMode> UnsettledPoles(const Frf& frf, const PlscfOptions& o, const PlscfResult& r) {
  PlscfOptions loose = o;
  loose.stable_damping = kLooseDamping;
  std::vector<ExtractedMode> out;
  for (const PlscfBlock& b : r.blocks) {
    for (ExtractedMode& m : ChoosePoles(loose, b.diagram, frf.frequencies_hz[r.lines.front()],
                                        frf.frequencies_hz[r.lines.back()], false)) {
      if (std::any_of(r.modes.begin(), r.modes.end(), [&](const ExtractedMode& q) {
            return std::abs(q.frequency_hz - m.frequency_hz) <= o.stable_frequency * q.frequency_hz;
          })) {
        continue;
      }
      OnAllInputs(frf, b, &m);
      out.push_back(std::move(m));
    }
  }
  return out;
}

// The real poles a misfit may lack (a slip lag's root with noise is seldom
// stable across orders, and below the band it leaves a 1 / s term): each
// block's negative real poles of the highest order with |σ| / 2π at most
// high_hz, and one at the band's lower edge; none within stable_frequency of
// one in `r`.
std::vector<double> RealPoleTrials(const Frf& frf, const PlscfOptions& o, const PlscfResult& r) {
  std::vector<double> out = {-2 * M_PI * frf.frequencies_hz[r.lines.front()]};
  for (const PlscfBlock& b : r.blocks) {
    if (b.diagram.empty()) continue;
    for (const PlscfPole& p : b.diagram.back().real_poles) {
      const double sigma = p.eigenvalue.real();
      if (sigma < 0 && -sigma / (2 * M_PI) <= frf.frequencies_hz[r.lines.back()]) out.push_back(sigma);
    }
  }
  out.erase(std::remove_if(out.begin(), out.end(), [&](double sigma) {
              return std::any_of(r.real_poles.begin(), r.real_poles.end(),
                                 [&](double q) { return SameRealPole(o, sigma, q); });
            }),
            out.end());
  return out;
}

// `modes` and `real_poles` on `r`'s lines, fitted by LSFD and refined.
PlscfResult Refitted(const Frf& frf, const PlscfOptions& o, const PlscfResult& r,
                     std::vector<ExtractedMode> modes, std::vector<double> real_poles) {
  PlscfResult trial;
  trial.lines = r.lines;
  trial.modes = std::move(modes);
  trial.real_poles = std::move(real_poles);
  std::vector<Complex> poles;
  for (const ExtractedMode& m : trial.modes) poles.push_back(m.eigenvalue);
  trial.functions = Lsfd(frf, trial.lines, poles, o.weigh_by_sigma, trial.real_poles);
  Refine(frf, o.weigh_by_sigma, &trial);
  return trial;
}

// `r`'s poles with `mode` or `real_pole` added, fitted by LSFD and refined.
PlscfResult WithPole(const Frf& frf, const PlscfOptions& o, const PlscfResult& r,
                     const ExtractedMode* mode, std::optional<double> real_pole) {
  std::vector<ExtractedMode> modes = r.modes;
  if (mode) modes.push_back(*mode);
  std::vector<double> real_poles = r.real_poles;
  if (real_pole) real_poles.push_back(*real_pole);
  return Refitted(frf, o, r, std::move(modes), std::move(real_poles));
}

// The weighted chi-square of mode m's part of the synthesis: removing it
// raises chi-square by at most this.
double Contribution(const Frf& frf, const PlscfResult& r, size_t m) {
  const Complex lambda = r.modes[m].eigenvalue;
  double sum = 0;
  for (size_t k = 0; k < frf.functions.size(); ++k) {
    const FrfFunction& f = frf.functions[k];
    const Complex residue = r.functions[k].residues[m];
    for (int l : r.lines) {
      const Complex s(0, 2 * M_PI * frf.frequencies_hz[l]);
      sum += std::norm((residue / (s - lambda) + std::conj(residue) / (s - std::conj(lambda))) / f.sigma[l]);
    }
  }
  return sum;
}

// Where the refined model misses the FRFs (weighted chi-square more than
// kMisfitSd of its sd, sqrt(2 dof), above its degrees of freedom), the
// unsettled pole or real pole that lowers chi-square most is added and all
// refined again, if it lowers chi-square by more than the 1e-3 critical
// value of its coordinates (a pole's 2 and 2 per function, a real pole's 1
// and 1 per function): a likelihood-ratio test. At most kMaxAddedPoles rounds.
constexpr double kMisfitSd = 5;
constexpr int kMaxAddedPoles = 2;
}  // namespace

void AddMissedPoles(const Frf& frf, const PlscfOptions& o, PlscfResult* r) {
  const double functions = static_cast<double>(frf.functions.size());
  for (int round = 0; round < kMaxAddedPoles; ++round) {
    const RefinementFit& fit = r->refinement;
    if (!fit.status.ok() || !fit.weighted ||
        fit.chi_square <= fit.degrees_of_freedom + kMisfitSd * std::sqrt(2.0 * fit.degrees_of_freedom)) {
      return;
    }
    PlscfResult best;
    double best_gain = 0;  // chi-square's drop beyond its critical value
    const auto consider = [&](PlscfResult trial, double coordinates) {
      if (!trial.refinement.status.ok()) return;
      const double gain = fit.chi_square - trial.refinement.chi_square - ChiSquareCritical(1e-3, coordinates);
      if (gain > best_gain) {
        best_gain = gain;
        best = std::move(trial);
      }
    };
    for (const ExtractedMode& candidate : UnsettledPoles(frf, o, *r)) {
      consider(WithPole(frf, o, *r, &candidate, std::nullopt), 2 + 2 * functions);
    }
    for (const double sigma : RealPoleTrials(frf, o, *r)) {
      consider(WithPole(frf, o, *r, nullptr, sigma), 1 + functions);
    }
    if (best_gain <= 0) return;
    r->modes = std::move(best.modes);
    r->functions = std::move(best.functions);
    r->real_poles = std::move(best.real_poles);
    r->refinement = best.refinement;
  }
}


// A pole whose contribution is below the 1e-3 critical value of its
// coordinates (2 and 2 per function): removing it raises chi-square by less
// than the likelihood-ratio test that adds poles asks of one. All such are
// dropped at once and the rest refined again (kept where that fails).
void DropInsignificantPoles(const Frf& frf, const PlscfOptions& o, PlscfResult* r) {
  if (!o.drop_insignificant || !r->refinement.status.ok() || !r->refinement.weighted) return;
  const double critical = ChiSquareCritical(1e-3, 2 + 2.0 * frf.functions.size());
  std::vector<ExtractedMode> kept;
  for (size_t m = 0; m < r->modes.size(); ++m) {
    if (Contribution(frf, *r, m) >= critical) kept.push_back(r->modes[m]);
  }
  if (kept.size() == r->modes.size() || kept.empty()) return;
  PlscfResult trial = Refitted(frf, o, *r, std::move(kept), r->real_poles);
  if (!trial.refinement.status.ok()) return;
  r->modes = std::move(trial.modes);
  r->functions = std::move(trial.functions);
  r->real_poles = std::move(trial.real_poles);
  r->refinement = trial.refinement;
}

}  // namespace ringid::plscf_internal
