// The poles of measured FRFs alone (estimation/poles.h).
#include "estimation/poles.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <utility>
#include <vector>

namespace ringid {
namespace {

constexpr int kFirstMaxOrder = 30;
constexpr int kLargestMaxOrder = 240;
constexpr double kExactFloor = 1e-3;

// H^T: each input an output and each output an input, the functions' pairs
// swapped; an output keeps the quantity of the functions it measured.
Frf Transposed(const Frf& frf) {
  Frf t;
  t.frequencies_hz = frf.frequencies_hz;
  for (const FrfOutput& o : frf.outputs) {
    FrfInput in;
    in.name = o.name;
    in.point = o.point;
    in.coordinates = o.coordinates;
    t.inputs.push_back(std::move(in));
  }
  for (const FrfInput& i : frf.inputs) {
    FrfOutput out;
    out.name = i.name;
    out.point = i.point;
    out.coordinates = i.coordinates;
    t.outputs.push_back(std::move(out));
  }
  for (const FrfFunction& f : frf.functions) {
    FrfFunction g = f;
    g.output = f.input;
    g.input = f.output;
    t.outputs[g.output].quantity = frf.outputs[f.output].quantity;
    t.functions.push_back(std::move(g));
  }
  return t;
}

bool AllSigmas(const Frf& frf) {
  return std::all_of(frf.functions.begin(), frf.functions.end(), [](const FrfFunction& f) {
    return f.sigma.size() == f.h.size() &&
           std::all_of(f.sigma.begin(), f.sigma.end(), [](double s) { return s > 0; });
  });
}

// The highest order: 30, doubled while pLSCF (without the refinement) finds
// more physical poles there.
int MaxOrder(const Frf& frf, int lines, const PlscfOptions& given) {
  PlscfOptions p = given;
  p.refine = false;
  p.max_order = std::min(kFirstMaxOrder, lines - 1);
  PlscfResult r;
  ExtractModes(frf, p, &r);
  int best = p.max_order;
  while (r.status.ok() && p.max_order < std::min(lines - 1, kLargestMaxOrder)) {
    const size_t found = r.modes.size();
    p.max_order = std::min({2 * p.max_order, lines - 1, kLargestMaxOrder});
    ExtractModes(frf, p, &r);
    if (!r.status.ok() || r.modes.size() <= found) break;
    best = p.max_order;
  }
  return best;
}

// Each line's sigma up to a factor per function: contract §9's shape,
// |H| with the floor of kFrfSigmaFloor of the function's peak (of the
// largest peak for a function that is zero).
void SigmaShape(Frf* frf) {
  double largest = 0;
  std::vector<double> peak;
  for (const FrfFunction& f : frf->functions) {
    peak.push_back(0);
    for (const std::complex<double>& h : f.h) peak.back() = std::max(peak.back(), std::abs(h));
    largest = std::max(largest, peak.back());
  }
  for (size_t k = 0; k < peak.size(); ++k) {
    FrfFunction& f = frf->functions[k];
    f.sigma.clear();
    f.coherence.reset();
    for (const std::complex<double>& h : f.h) f.sigma.push_back(FrfSigma(1, h, peak[k] > 0 ? peak[k] : largest));
  }
}

// Each function's factor from the residuals of `r`, fitted with the shape's
// weights (estimation/poles.h).
bool NoiseFromResiduals(const PlscfResult& r, Frf* frf) {
  if (!r.status.ok() || r.functions.size() != frf->functions.size() || r.lines.empty()) return false;
  std::vector<std::complex<double>> poles;
  for (const ExtractedMode& m : r.modes) poles.push_back(m.eigenvalue);
  const double values = 2.0 * r.lines.size() * frf->functions.size();
  const int dof = r.refinement.status.ok() ? r.refinement.degrees_of_freedom : 0;
  const double scale = dof > 0 ? values / dof : 1;
  std::vector<double> level(frf->functions.size());
  for (size_t k = 0; k < level.size(); ++k) {
    const FrfFunction& f = frf->functions[k];
    double sum = 0;
    for (int l : r.lines) {
      sum += std::norm((r.functions[k].At(frf->frequencies_hz[l], poles, r.real_poles) - f.h[l]) / f.sigma[l]);
    }
    level[k] = std::sqrt(sum / (2.0 * r.lines.size()) * scale);
  }
  // A function fitted exactly (zero in the file, say) at a thousandth of
  // the noisiest one's level.
  const double largest = *std::max_element(level.begin(), level.end());
  if (!(largest > 0) || !std::isfinite(largest)) return false;
  for (size_t k = 0; k < level.size(); ++k) {
    for (double& sigma : frf->functions[k].sigma) sigma *= std::max(level[k], kExactFloor * largest);
  }
  return true;
}

}  // namespace

bool PolesOptions::IsValid(std::string* why) const {
  if (!(band_low_hz >= 0 && band_high_hz > band_low_hz)) {
    *why = "need 0 <= low < high";
    return false;
  }
  return true;
}

void FindPoles(const Frf& frf, const PolesOptions& o, FoundPoles* out) {
  *out = FoundPoles{};
  std::string why;
  if (!o.IsValid(&why)) {
    out->status = Status::InvalidInput(why);
    return;
  }
  const int lines = static_cast<int>(std::count_if(
      frf.frequencies_hz.begin(), frf.frequencies_hz.end(),
      [&](double hz) { return hz > 0 && hz >= o.band_low_hz && hz <= o.band_high_hz; }));
  if (lines < kMinPoleLines) {
    out->status = Status::InvalidInput(std::to_string(lines) + " lines in the band: poles need at least " +
                                       std::to_string(kMinPoleLines));
    return;
  }
  out->transposed = frf.inputs.size() > frf.outputs.size();
  out->fitted = out->transposed ? Transposed(frf) : frf;
  out->noise_from_residuals = !AllSigmas(out->fitted);
  PlscfOptions p;
  p.band_low_hz = o.band_low_hz;
  p.band_high_hz = o.band_high_hz;
  // With the shape alone the scale is unknown: no pole dropped or added by
  // chi-square until the noise is estimated.
  p.drop_insignificant = !out->noise_from_residuals;
  if (out->noise_from_residuals) SigmaShape(&out->fitted);
  p.max_order = out->max_order = MaxOrder(out->fitted, lines, p);
  ExtractModes(out->fitted, p, &out->plscf);
  if (out->noise_from_residuals) {
    if (!NoiseFromResiduals(out->plscf, &out->fitted)) {
      out->status = out->plscf.status.ok() ? Status::Failed("no noise level: " + out->plscf.status.message)
                                           : out->plscf.status;
      return;
    }
    p.drop_insignificant = true;
    ExtractModes(out->fitted, p, &out->plscf);
  }
  out->status = out->plscf.status;
}

}  // namespace ringid
