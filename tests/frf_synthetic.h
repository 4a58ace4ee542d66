// Synthetic FRFs for the modal extraction's tests (plscf_test, modal_refine_test):
// an Frf from a closed-form H, circular noise at contract §9's sigma, the car
// tire's standing hammer test from the model, and two close, damped modes.
#ifndef RINGID_TESTS_FRF_SYNTHETIC_H_
#define RINGID_TESTS_FRF_SYNTHETIC_H_

#include <algorithm>
#include <cmath>
#include <complex>
#include <functional>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "datasets/frf.h"
#include "datasets/synthetic.h"
#include "model/frequency_response.h"
#include "model/rigid_ring_model.h"

namespace ringid::testing {

// An Frf of `outputs` x `inputs` (displacements, every pair) whose values
// are h(hz) at lines low..high every step, without sigma.
inline Frf MakeFrf(int outputs, int inputs, double low, double high, double step,
                   const std::function<Eigen::MatrixXcd(double)>& h) {
  Frf frf;
  frf.inputs.resize(inputs);
  frf.outputs.resize(outputs);
  for (double hz = low; hz <= high + 1e-9; hz += step) frf.frequencies_hz.push_back(hz);
  for (int o = 0; o < outputs; ++o) {
    for (int i = 0; i < inputs; ++i) frf.functions.push_back({o, i, {}, {}, std::nullopt});
  }
  for (double hz : frf.frequencies_hz) {
    const Eigen::MatrixXcd value = h(hz);
    for (FrfFunction& f : frf.functions) f.h.push_back(value(f.output, f.input));
  }
  return frf;
}

// Adds circular noise of sd `relative` x FrfSigma to each value (of the
// noise-free value and its function's peak), and sets sigma so. A function
// that is zero (across the planes) has the floor of the Frf's largest peak,
// as its sensor would: sigma is positive (contract §9).
inline void AddNoise(double relative, std::mt19937_64* rng, Frf* frf) {
  std::normal_distribution<double> normal;
  double largest = 0;
  for (const FrfFunction& f : frf->functions) {
    for (const std::complex<double>& h : f.h) largest = std::max(largest, std::abs(h));
  }
  for (FrfFunction& f : frf->functions) {
    double peak = 0;
    for (const std::complex<double>& h : f.h) peak = std::max(peak, std::abs(h));
    if (peak == 0) peak = largest;
    f.sigma.clear();
    for (std::complex<double>& h : f.h) {
      const double sigma = FrfSigma(relative, h, peak);
      f.sigma.push_back(sigma);
      h += std::complex<double>(sigma * normal(*rng), sigma * normal(*rng));
    }
  }
}

// The car tire's standing hammer test (datasets/synthetic.h: 4 blows x 7
// accelerometers), noise-free from the model's H.
inline Frf CarTireHammer(double low_hz = 5, double high_hz = 250, double step_hz = 0.5) {
  Frf frf = HammerTest(0.31, low_hz, high_hz, step_hz);
  ResponseRequest request;
  for (const FrfInput& in : frf.inputs) {
    request.inputs.push_back(
        {std::nullopt, Coordinates(in.coordinates.begin(), in.coordinates.end())});
  }
  for (const FrfOutput& out : frf.outputs) {
    request.outputs.push_back({std::nullopt,
                               Coordinates(out.coordinates.begin(), out.coordinates.end()),
                               static_cast<int>(out.quantity), out.point->on == FrfBody::kRim});
  }
  for (const FrfFunction& f : frf.functions) request.pairs.push_back({f.output, f.input});
  request.frequencies_hz = frf.frequencies_hz;
  const ResponseResult h = FrequencyResponse(RigidRingModel(), ExampleCarTire(), 0, request);
  EXPECT_TRUE(h.ok) << h.error;
  for (int f = 0; f < static_cast<int>(frf.functions.size()); ++f) {
    for (int l = 0; l < h.H.rows(); ++l) frf.functions[f].h[l] = h.H(l, f);
    frf.functions[f].sigma.clear();
  }
  return frf;
}

// The car tire's drum test at speed_m_s (datasets/synthetic.h: contact
// forces to the held axle's channels, in-plane per in-plane force and
// out-of-plane per lateral force), noise-free from the model's H.
inline Frf CarTireDrum(double speed_m_s, double low_hz = 4, double high_hz = 160,
                       double step_hz = 0.5) {
  Frf frf = DrumTest(low_hz, high_hz, step_hz);
  ResponseRequest request;
  for (const FrfInput& in : frf.inputs) request.inputs.push_back({in.contact, {}});
  for (const FrfOutput& out : frf.outputs) request.outputs.push_back({out.channel, {}, 0});
  for (const FrfFunction& f : frf.functions) request.pairs.push_back({f.output, f.input});
  request.frequencies_hz = frf.frequencies_hz;
  const ResponseResult h = FrequencyResponse(RigidRingModel(), ExampleCarTire(), speed_m_s, request);
  EXPECT_TRUE(h.ok) << h.error;
  for (int f = 0; f < static_cast<int>(frf.functions.size()); ++f) {
    for (int l = 0; l < h.H.rows(); ++l) frf.functions[f].h[l] = h.H(l, f);
    frf.functions[f].sigma.clear();
  }
  return frf;
}

// Two modes 3 Hz apart (80 and 83 Hz damped) at damping ratio 0.06, their
// half-power bands overlapping, and a third at 40 Hz (0.03): a proportionally
// damped system of three coordinates with mass-normalised shapes phi, its
// receptance at the three per forces on the first and last.
struct CloseModes {
  double zeta[3] = {0.03, 0.06, 0.06}, damped_hz[3] = {40, 80, 83};
  Eigen::Matrix3d phi;
  std::vector<std::complex<double>> poles;  // λ = -ζ ω_n + i ω_d
  CloseModes() {
    phi << 0.5, 0.8, 0.3, 0.7, -0.2, 0.9, 0.4, -0.6, -0.5;
    for (int r = 0; r < 3; ++r) {
      const double wn = 2 * M_PI * damped_hz[r] / std::sqrt(1 - zeta[r] * zeta[r]);
      poles.emplace_back(-zeta[r] * wn, 2 * M_PI * damped_hz[r]);
    }
  }
  Eigen::MatrixXcd H(double hz) const {
    const double w = 2 * M_PI * hz;
    Eigen::MatrixXcd value = Eigen::MatrixXcd::Zero(3, 2);
    for (int r = 0; r < 3; ++r) {
      const double wn = std::abs(poles[r]);
      const std::complex<double> modal = 1.0 / std::complex<double>(wn * wn - w * w,
                                                                     2 * zeta[r] * wn * w);
      for (int o = 0; o < 3; ++o) {
        value(o, 0) += phi(o, r) * phi(0, r) * modal;
        value(o, 1) += phi(o, r) * phi(2, r) * modal;
      }
    }
    return value;
  }
  // Lines 5..250 Hz every 0.5 Hz, noise-free.
  Frf Measured() const {
    return MakeFrf(3, 2, 5, 250, 0.5, [this](double hz) { return H(hz); });
  }
};

}  // namespace ringid::testing

#endif  // RINGID_TESTS_FRF_SYNTHETIC_H_
