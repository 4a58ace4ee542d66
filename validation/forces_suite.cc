// bench --suite=forces (issue 23): the lug forces recovered from noisy axle
// responses, with the true parameters and with identified ones, against
// the unweighted pseudo-inverse and Tikhonov with the L-curve.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <tuple>

#include <Eigen/SVD>

#include "datasets/response_dataset.h"
#include "datasets/synthetic.h"
#include "estimation/forces.h"
#include "estimation/identify.h"
#include "estimation/statistics.h"
#include "model/campbell.h"
#include "model/forced_response.h"
#include "validation/suites.h"

namespace ringid {
namespace {

using Complex = std::complex<double>;

// |Y| / (10 sqrt 2) on re and on im: 20 dB.
const double kResponseNoise = 1 / (10 * std::sqrt(2.0));
const std::vector<double> kModalSpeeds = {0, 6, 12};
constexpr int kLugs = 20, kOrders = 5;
const std::vector<AxleChannel> kChannels = {AxleChannel::kForceX, AxleChannel::kForceZ,
                                            AxleChannel::kForceY, AxleChannel::kMomentX,
                                            AxleChannel::kMomentZ};

std::array<Complex, kNumLugForces> TrueForces(int k) {
  return {std::polar(300.0 / k, 0.7 * k), std::polar(900.0 / k, 0.7 * k + 1),
          std::polar(150.0 / k, 0.7 * k + 2)};
}

// Tikhonov on A F = y with lambda at the L-curve's corner: the largest
// curvature of (log |A F - y|, log |F|) over 60 values of log lambda spanning
// the singular values (Hansen's L-curve criterion).
Eigen::VectorXcd Tikhonov(const Eigen::MatrixXcd& A, const Eigen::VectorXcd& y) {
  const Eigen::JacobiSVD<Eigen::MatrixXcd> svd(A, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd s = svd.singularValues();
  const Eigen::VectorXcd beta = svd.matrixU().adjoint() * y;
  const int n = 60;
  const double lo = std::log(s(s.size() - 1) * 1e-3), hi = std::log(s(0));
  std::vector<double> rho(n), eta(n);
  std::vector<Eigen::VectorXcd> F(n);
  for (int j = 0; j < n; ++j) {
    const double lambda = std::exp(lo + (hi - lo) * j / (n - 1));
    Eigen::VectorXcd coefficients(s.size());
    for (int i = 0; i < s.size(); ++i) coefficients(i) = s(i) / (s(i) * s(i) + lambda * lambda) * beta(i);
    F[j] = svd.matrixV() * coefficients;
    rho[j] = std::log((A * F[j] - y).norm() + 1e-300);
    eta[j] = std::log(F[j].norm() + 1e-300);
  }
  int best = n / 2;
  double curvature = -INFINITY;
  for (int j = 1; j + 1 < n; ++j) {
    const double r1 = (rho[j + 1] - rho[j - 1]) / 2, e1 = (eta[j + 1] - eta[j - 1]) / 2;
    const double r2 = rho[j + 1] - 2 * rho[j] + rho[j - 1], e2 = eta[j + 1] - 2 * eta[j] + eta[j - 1];
    const double k = (r1 * e2 - r2 * e1) / std::pow(r1 * r1 + e1 * e1, 1.5);
    if (std::isfinite(k) && k > curvature) curvature = k, best = j;
  }
  return F[best];
}

// What is tallied of one method at one force-order over the replicates.
struct Tally {
  Complex sum = 0;
  long n = 0;
};
struct MethodTally {
  std::map<std::tuple<int, int, int>, Tally> cells;  // (condition, order, force)
  std::vector<double> errors;                        // |F^ - F| / |F|
  double z2 = 0;
  long z_n = 0, inside_total = 0, inside_measurement = 0, intervals = 0;
  long resonance_total = 0, resonance_measurement = 0, resonance_intervals = 0;

  void Add(int c, int k, int f, Complex estimate, Complex truth) {
    Tally& t = cells[{c, k, f}];
    t.sum += estimate;
    ++t.n;
    errors.push_back(std::abs(estimate - truth) / std::abs(truth));
  }
  void AddIntervals(const ForceEstimate& e, Complex truth, bool resonance) {
    for (const double d : {e.value.real() - truth.real(), e.value.imag() - truth.imag()}) {
      z2 += d * d / (e.std_measurement * e.std_measurement);
      ++z_n;
      const bool total = std::abs(d) <= kNormal95 * e.std_total;
      const bool measurement = std::abs(d) <= kNormal95 * e.std_measurement;
      inside_total += total;
      inside_measurement += measurement;
      ++intervals;
      if (resonance) {
        resonance_total += total;
        resonance_measurement += measurement;
        ++resonance_intervals;
      }
    }
  }
  ForcesMethodRow Row(ForcesMethod m, bool intervals_kept) const {
    ForcesMethodRow r;
    r.method = m;
    r.estimates = static_cast<long>(errors.size());
    for (const auto& [key, t] : cells) {
      const Complex truth = TrueForces(std::get<1>(key))[std::get<2>(key)];
      r.bias_max = std::max(r.bias_max, std::abs(t.sum / double(t.n) - truth) / std::abs(truth));
    }
    double e2 = 0;
    for (double e : errors) e2 += e * e;
    r.rms_error = errors.empty() ? NAN : std::sqrt(e2 / errors.size());
    std::vector<double> sorted = errors;
    std::sort(sorted.begin(), sorted.end());
    r.median_error = sorted.empty() ? NAN : sorted[sorted.size() / 2];
    if (intervals_kept && intervals > 0) {
      r.rms_z_measurement = std::sqrt(z2 / z_n);
      r.coverage_total = double(inside_total) / intervals;
      r.coverage_measurement = double(inside_measurement) / intervals;
      if (resonance_intervals > 0) {
        r.coverage_total_at_resonance = double(resonance_total) / resonance_intervals;
        r.coverage_measurement_at_resonance = double(resonance_measurement) / resonance_intervals;
      }
    }
    return r;
  }
};

}  // namespace

const ForcesMethodRow* ForcesSuite::Find(ForcesMethod m) const {
  for (const ForcesMethodRow& r : methods) {
    if (r.method == m) return &r;
  }
  return nullptr;
}

bool ForcesSuite::Unbiased() const {
  const ForcesMethodRow* r = Find(ForcesMethod::kTrueParameters);
  return r && r->bias_max <= bias_max_allowed;
}

bool ForcesSuite::StdIsRight() const {
  const ForcesMethodRow* r = Find(ForcesMethod::kTrueParameters);
  return r && r->rms_z_measurement && std::abs(*r->rms_z_measurement - 1) <= rms_z_tolerance;
}

bool ForcesSuite::TotalCovers() const {
  const ForcesMethodRow* r = Find(ForcesMethod::kIdentified);
  const auto in = [&](const std::optional<double>& c) {
    return c && *c >= coverage_range.first && *c <= coverage_range.second;
  };
  return r && in(r->coverage_total) && in(r->coverage_total_at_resonance);
}

bool ForcesSuite::MeasurementUnderCovers() const {
  const ForcesMethodRow* r = Find(ForcesMethod::kIdentified);
  return r && r->coverage_measurement && r->coverage_total &&
         *r->coverage_measurement < std::min(0.95, *r->coverage_total);
}

Status RunForcesSuite(const SuiteOptions& o, ForcesSuite* suite) {
  if (o.replicates < 1) return Status::InvalidInput("replicates: must be at least 1");
  const auto start = std::chrono::steady_clock::now();
  const Parameters truth = ExampleCarTire();
  const RigidRingModel model;
  // The speed where order 1 meets the vertical mode: a response on resonance.
  std::vector<double> grid;
  for (int i = 1; i <= 60; ++i) grid.push_back(0.5 * i);
  double resonance = NAN;
  for (const CriticalSpeed& c : CriticalSpeeds(model, truth, kLugs, grid, 1)) {
    if (c.order == 1 && c.label == ModeLabel::kVertical) resonance = c.speed_m_s;
  }
  if (!std::isfinite(resonance)) return Status::Failed("order 1 meets no vertical mode below 30 m/s");
  const std::vector<double> speeds = {6, resonance, 15};
  std::mt19937_64 rng(o.seed);
  std::map<ForcesMethod, MethodTally> tallies;
  for (int rep = 0; rep < o.replicates; ++rep) {
    Dataset modal;
    if (Status s = RollingDataset(truth, kModalSpeeds, &rng, &modal); !s.ok()) return s;
    ResponseDataset data;
    std::string why;
    if (!SimulateResponses(model, truth, kLugs, speeds, kOrders, kChannels, TrueForces,
                           kResponseNoise, &rng, &data, &why)) {
      return Status::Failed(why);
    }
    IdentifyOptions io;
    io.starts = 1;
    io.residuals.derivatives = o.derivatives;
    IdentifyResult fit;
    Identify(model, modal, io, &fit);
    ForceParameters exact;
    exact.shared = truth;
    const ForceParameters identified = ForceParameters::From(fit);
    ForcesResult with_truth, with_fit;
    EstimateForces(model, exact, data, ForcesOptions{}, &with_truth);
    if (!fit.status.ok()) {
      ++suite->failed_fits;
    } else {
      EstimateForces(model, identified, data, ForcesOptions{}, &with_fit);
    }
    for (size_t c = 0; c < data.conditions.size(); ++c) {
      const ResponseCondition& rc = data.conditions[c];
      for (int k = 1; k <= kOrders; ++k) {
        const auto F = TrueForces(k);
        const bool on_resonance = c == 1 && k == 1;
        const auto take = [&](const ForcesResult& r, ForcesMethod m) {
          if (!r.status.ok()) return;
          for (const auto& [force, e] : r.conditions[c].orders[k - 1].forces) {
            const int f = static_cast<int>(force);
            tallies[m].Add(static_cast<int>(c), k, f, e.value, F[f]);
            tallies[m].AddIntervals(e, F[f], on_resonance);
          }
        };
        take(with_truth, ForcesMethod::kTrueParameters);
        if (!fit.status.ok()) continue;
        take(with_fit, ForcesMethod::kIdentified);
        // The same identified response, unweighted.
        const Parameters p = identified.In(rc);
        AxleResponseMatrix H;
        const double hz = LugOrderHz(k, kLugs, p[Param::r_e0], rc.speed_m_s);
        if (!AxleResponse(model, p, rc.speed_m_s, hz, &H, &why)) continue;
        const OrderResponse& order = rc.orders[k - 1];
        Eigen::MatrixXcd A(order.channels.size(), kNumLugForces);
        Eigen::VectorXcd y(order.channels.size());
        int row = 0;
        for (const auto& [channel, phasor] : order.channels) {
          A.row(row) = H.row(static_cast<int>(channel));
          y(row++) = phasor.value;
        }
        const Eigen::VectorXcd pinv =
            A.jacobiSvd(Eigen::ComputeThinU | Eigen::ComputeThinV).solve(y);
        const Eigen::VectorXcd tikhonov = Tikhonov(A, y);
        for (int f = 0; f < kNumLugForces; ++f) {
          tallies[ForcesMethod::kPseudoInverse].Add(static_cast<int>(c), k, f, pinv(f), F[f]);
          tallies[ForcesMethod::kTikhonov].Add(static_cast<int>(c), k, f, tikhonov(f), F[f]);
        }
      }
    }
    if (o.on_case) o.on_case(rep + 1, o.replicates);
  }
  suite->tire = "example car tire (205/60R15 belt, 4 kN load)";
  suite->lugs_per_revolution = kLugs;
  suite->speeds_m_s = speeds;
  suite->modal_speeds_m_s = kModalSpeeds;
  suite->orders = kOrders;
  suite->replicates = o.replicates;
  suite->response_noise = kResponseNoise;
  suite->resonance_speed_m_s = resonance;
  for (const auto& [method, tally] : tallies) {
    const bool intervals = method == ForcesMethod::kTrueParameters || method == ForcesMethod::kIdentified;
    suite->methods.push_back(tally.Row(method, intervals));
  }
  suite->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Success();
}

}  // namespace ringid
