// pLSCF, its stabilisation diagram, the physical poles and LSFD
// (estimation/plscf.h, issue 37 step 1) against closed forms: a 3-DOF
// system written here (H = (K + iωC - ω²M)^-1, its poles and residues from
// its own eigenproblem), the car tire's hammer test against the model's
// modal solution, and two close, damped modes with noise.
#include "estimation/plscf.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <functional>
#include <random>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "datasets/synthetic.h"
#include "model/frequency_response.h"
#include "model/rigid_ring_model.h"
#include "tests/frf_synthetic.h"

namespace ringid {
namespace {

using cd = std::complex<double>;
using testing::AddNoise;
using testing::CarTireDrum;
using testing::CarTireHammer;
using testing::MakeFrf;

// M, C, K of three masses in a chain (ground - 1 - 2 - 3), the dampers not
// proportional to the springs.
struct ThreeDof {
  Eigen::Matrix3d M, C, K;
  ThreeDof() {
    M = Eigen::Vector3d(2.0, 1.5, 1.0).asDiagonal();
    const double k[] = {4e4, 3e4, 2e4}, c[] = {30, 8, 12};
    K << k[0] + k[1], -k[1], 0, -k[1], k[1] + k[2], -k[2], 0, -k[2], k[2];
    C << c[0] + c[1], -c[1], 0, -c[1], c[1] + c[2], -c[2], 0, -c[2], c[2];
  }
  // Receptance at the three masses per force on each.
  Eigen::MatrixXcd G(double hz) const {
    const double w = 2 * M_PI * hz;
    const Eigen::Matrix3cd D = (K - w * w * M).cast<cd>() + cd(0, w) * C.cast<cd>();
    return D.inverse();
  }
  // Per force on masses 1 and 3.
  Eigen::MatrixXcd H(double hz) const {
    const Eigen::MatrixXcd g = G(hz);
    Eigen::MatrixXcd h(3, 2);
    h << g.col(0), g.col(2);
    return h;
  }
  // The state-space eigenproblem [0 I; -K -C] v = λ [I 0; 0 M] v: its
  // eigenvalues with Im > 0, and each one's residue matrix of H (3 x 3,
  // columns per force), from the standard form A = B^-1 [0 I; -K -C]:
  // H(s) = [I 0] (sI - A)^-1 [0; M^-1] = sum_r V_r W_r [0; M^-1] / (s - λ_r).
  std::pair<std::vector<cd>, std::vector<Eigen::Matrix3cd>> Modes() const {
    std::pair<std::vector<cd>, std::vector<Eigen::Matrix3cd>> out;
    Modes(&out.first, &out.second);
    return out;
  }
  void Modes(std::vector<cd>* poles, std::vector<Eigen::Matrix3cd>* residues) const {
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(6, 6), b = Eigen::MatrixXd::Identity(6, 6);
    a.topRightCorner(3, 3).setIdentity();
    a.bottomLeftCorner(3, 3) = -K;
    a.bottomRightCorner(3, 3) = -C;
    b.bottomRightCorner(3, 3) = M;
    const Eigen::GeneralizedEigenSolver<Eigen::MatrixXd> ges(a, b);
    const Eigen::VectorXcd lambda = ges.eigenvalues();
    const Eigen::EigenSolver<Eigen::MatrixXd> es(b.inverse() * a);
    const Eigen::MatrixXcd v = es.eigenvectors(), w = v.inverse();
    const Eigen::Matrix3cd minv = M.inverse().cast<cd>();
    for (int r = 0; r < 6; ++r) {
      if (!(lambda(r).imag() > 0)) continue;
      poles->push_back(lambda(r));
      int e = 0;  // the standard form's same eigenvalue
      for (int q = 1; q < 6; ++q) {
        if (std::abs(es.eigenvalues()(q) - lambda(r)) < std::abs(es.eigenvalues()(e) - lambda(r)))
          e = q;
      }
      residues->push_back(v.col(e).head(3) * (w.row(e).tail(3) * minv));
    }
  }
};

// The extracted mode nearest `lambda`, or null.
const ExtractedMode* Nearest(const PlscfResult& r, cd lambda) {
  const ExtractedMode* best = nullptr;
  for (const ExtractedMode& m : r.modes) {
    if (!best || std::abs(m.eigenvalue - lambda) < std::abs(best->eigenvalue - lambda)) best = &m;
  }
  return best;
}

double Seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

TEST(PlscfTest, ANoiseFreeThreeDofSystemGivesItsPolesAndResidues) {
  const ThreeDof system;
  const auto [poles, residues] = system.Modes();
  ASSERT_EQ(poles.size(), 3u);
  const Frf frf = MakeFrf(3, 2, 1, 100, 0.5, [&](double hz) { return system.H(hz); });
  PlscfOptions o;
  PlscfResult r;
  const auto start = std::chrono::steady_clock::now();
  ExtractModes(frf, o, &r);
  std::printf("3-DOF: %.3f s\n", Seconds(start));
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_EQ(r.modes.size(), 3u);
  for (size_t p = 0; p < poles.size(); ++p) {
    const ExtractedMode& m = *Nearest(r, poles[p]);
    const double error = std::abs(m.eigenvalue - poles[p]) / std::abs(poles[p]);
    std::printf("pole %.6f Hz, zeta %.6f: relative error %.2e (order %d, %d stable orders)\n",
                poles[p].imag() / (2 * M_PI), -poles[p].real() / std::abs(poles[p]), error, m.order,
                m.stable_orders);
    EXPECT_LT(error, 1e-6);
    EXPECT_NEAR(m.frequency_hz, poles[p].imag() / (2 * M_PI), 1e-6 * m.frequency_hz);
    // LSFD's residues at forces 1 and 3 against the closed form's.
    const double scale = residues[p].cwiseAbs().maxCoeff();
    for (int o2 = 0; o2 < 3; ++o2) {
      for (int i = 0; i < 2; ++i) {
        const cd expected = residues[p](o2, i == 0 ? 0 : 2);
        EXPECT_LT(std::abs(m.residues(o2, i) - expected), 1e-5 * scale)
            << "mode " << p << ", output " << o2 << ", input " << i << ": " << m.residues(o2, i)
            << " vs " << expected;
      }
    }
  }
}

// At the highest orders 20 and 40 alike: the stable poles do not depend on
// the highest order once it is high enough.
TEST(PlscfTest, ANoiseFreeHammerTestGivesTheModelsPolesAtAnyHighEnoughOrder) {
  const Frf frf = CarTireHammer();
  const ModalSolution truth = RigidRingModel().Solve(ExampleCarTire());
  ASSERT_TRUE(truth.ok) << truth.error;
  PlscfResult r;
  for (int max_order : {20, 40}) {
    PlscfOptions o;
    o.max_order = max_order;
    const auto start = std::chrono::steady_clock::now();
    ExtractModes(frf, o, &r);
    std::printf("hammer test, 28 FRFs x %zu lines, orders 1..%d: %.3f s\n",
                frf.frequencies_hz.size(), o.max_order, Seconds(start));
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    EXPECT_EQ(r.modes.size(), truth.modes.size()) << "orders 1.." << max_order;
    for (const Mode& mode : truth.modes) {
      ASSERT_TRUE(mode.frequency_hz > 5 && mode.frequency_hz < 250) << LabelName(mode.label);
      const ExtractedMode& m = *Nearest(r, mode.eigenvalue);
      const double error = std::abs(m.eigenvalue - mode.eigenvalue) / std::abs(mode.eigenvalue);
      std::printf("%s %.4f Hz, zeta %.4f: relative error %.2e (order %d, %d stable orders)\n",
                  LabelName(mode.label), mode.frequency_hz, mode.damping_ratio, error, m.order,
                  m.stable_orders);
      EXPECT_LT(error, 1e-6) << LabelName(mode.label) << ", orders 1.." << max_order;
    }
  }
  for (const Mode& mode : truth.modes) {
    const ExtractedMode& m = *Nearest(r, mode.eigenvalue);
    // The shape on the outputs: the residue of an accelerance at λ is λ²
    // times the receptance's, whose outputs see the eigenvector through
    // their combinations.
    Eigen::VectorXcd expected(frf.outputs.size());
    for (size_t out = 0; out < frf.outputs.size(); ++out) {
      expected(out) = 0;
      for (const auto& [dof, c] : frf.outputs[out].coordinates) {
        expected(out) += c * mode.shape(static_cast<int>(dof));
      }
    }
    expected *= mode.eigenvalue * mode.eigenvalue;
    const double mac =
        std::norm(expected.dot(m.shape)) / (expected.squaredNorm() * m.shape.squaredNorm());
    EXPECT_GT(mac, 1 - 1e-9) << LabelName(mode.label);
  }
  // LSFD's modal model (the lower residual holding the accelerances' direct
  // term) gives back every function.
  std::vector<cd> poles;
  for (const ExtractedMode& m : r.modes) poles.push_back(m.eigenvalue);
  // Relative to the largest value its output shows (a function across the
  // planes is zero).
  std::vector<double> peak(frf.outputs.size(), 0.0);
  for (const FrfFunction& f : frf.functions) {
    for (const cd& h : f.h) peak[f.output] = std::max(peak[f.output], std::abs(h));
  }
  double worst = 0;
  for (size_t f = 0; f < frf.functions.size(); ++f) {
    const FrfFunction& fn = frf.functions[f];
    for (size_t l = 0; l < frf.frequencies_hz.size(); ++l) {
      const double gap = std::abs(r.functions[f].At(frf.frequencies_hz[l], poles) - fn.h[l]);
      worst = std::max(worst, gap / peak[fn.output]);
    }
  }
  std::printf("LSFD's functions against the model's: largest gap %.1e of the output's peak\n",
              worst);
  EXPECT_LT(worst, 1e-6);
}

// With 2 % noise, the physical poles at the highest orders 20, 30 and 40
// are the same seven modes (at 40, this draw's longitudinal mode, damped
// 0.011, wanders in damping across orders by more than the window, and its
// remainder is no second mode), each within issue 37's acceptance of the
// model's (0.5 % in frequency, 10 % in damping) and within the stability
// tolerance in frequency (1 %) of the highest order's. Refined
// (estimation/modal_refine.h), they are one optimum: the same at each
// highest order to 1e-3 of their standard errors.
TEST(PlscfTest, WithNoiseThePhysicalPolesAreTheSameModesAtEachHighestOrder) {
  Frf frf = CarTireHammer();
  std::mt19937_64 rng(102);
  AddNoise(0.02, &rng, &frf);
  const ModalSolution truth = RigidRingModel().Solve(ExampleCarTire());
  std::vector<PlscfResult> results;
  for (int max_order : {20, 30, 40}) {
    PlscfOptions o;
    o.max_order = max_order;
    results.emplace_back();
    const auto start = std::chrono::steady_clock::now();
    ExtractModes(frf, o, &results.back());
    std::printf("orders 1..%d: %.3f s\n", max_order, Seconds(start));
    ASSERT_TRUE(results.back().status.ok()) << results.back().status.message;
    ASSERT_EQ(results.back().modes.size(), truth.modes.size()) << "highest order " << max_order;
    ASSERT_TRUE(results.back().refinement.status.ok()) << results.back().refinement.status.message;
  }
  for (size_t k = 0; k < truth.modes.size(); ++k) {
    const Mode& mode = truth.modes[k];
    for (const PlscfResult& r : results) {
      const ExtractedMode& m = r.modes[k];
      const ExtractedMode& last = results.back().modes[k];
      std::printf("%s: %.3f Hz (%+.3f %%), zeta %.4f (%+.1f %%), order %d, %d stable orders\n",
                  LabelName(mode.label), m.frequency_hz,
                  100 * (m.frequency_hz / mode.frequency_hz - 1), m.damping_ratio,
                  100 * (m.damping_ratio / mode.damping_ratio - 1), m.order, m.stable_orders);
      EXPECT_LT(std::abs(m.frequency_hz / mode.frequency_hz - 1), 0.005) << LabelName(mode.label);
      EXPECT_LT(std::abs(m.damping_ratio / mode.damping_ratio - 1), 0.10) << LabelName(mode.label);
      EXPECT_LT(std::abs(m.frequency_hz / last.frequency_hz - 1), PlscfOptions{}.stable_frequency)
          << LabelName(mode.label);
      EXPECT_LT(std::abs(m.frequency_hz - last.frequency_hz), 1e-3 * last.frequency_std_hz)
          << LabelName(mode.label);
      EXPECT_LT(std::abs(m.damping_ratio - last.damping_ratio), 1e-3 * last.damping_ratio_std)
          << LabelName(mode.label);
    }
  }
}

// Two modes 3 Hz apart at damping ratio 0.06 (testing::CloseModes), 2 %
// noise. Both close modes are found within issue 37's acceptance (0.5 % in
// frequency, 10 % in damping) at each of five noise draws.
TEST(PlscfTest, TwoModesThreeHertzApartAtDamping006WithNoiseAreBothFound) {
  const testing::CloseModes system;
  const std::vector<cd>& poles = system.poles;
  const double* damped_hz = system.damped_hz;
  double worst_f = 0, worst_zeta = 0;
  for (int seed = 0; seed < 5; ++seed) {
    Frf frf = system.Measured();
    std::mt19937_64 rng(seed);
    AddNoise(0.02, &rng, &frf);
    PlscfResult r;
    ExtractModes(frf, PlscfOptions{}, &r);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    EXPECT_EQ(r.modes.size(), 3u) << "seed " << seed;
    for (int p = 1; p < 3; ++p) {
      const ExtractedMode& m = *Nearest(r, poles[p]);
      const double zeta_true = -poles[p].real() / std::abs(poles[p]);
      const double ef = m.frequency_hz / damped_hz[p] - 1, ez = m.damping_ratio / zeta_true - 1;
      std::printf("seed %d, %.0f Hz: %.3f Hz (%+.3f %%), zeta %.4f (%+.2f %%), %d stable orders\n",
                  seed, damped_hz[p], m.frequency_hz, 100 * ef, m.damping_ratio, 100 * ez,
                  m.stable_orders);
      EXPECT_LT(std::abs(ef), 0.005) << "seed " << seed << ", " << damped_hz[p] << " Hz";
      EXPECT_LT(std::abs(ez), 0.10) << "seed " << seed << ", " << damped_hz[p] << " Hz";
      worst_f = std::max(worst_f, std::abs(ef));
      worst_zeta = std::max(worst_zeta, std::abs(ez));
    }
    EXPECT_NE(Nearest(r, poles[1]), Nearest(r, poles[2])) << "seed " << seed;
  }
  std::printf("close modes, worst over 5 draws: frequency %.3f %%, damping %.2f %%\n",
              100 * worst_f, 100 * worst_zeta);
}

// A missing pair: the output lacking it is left out of pLSCF and keeps its
// other residues; an input without a function is in no block; with bad
// options, nothing runs.
TEST(PlscfTest, AnOutputMissingAnInputJoinsOnlyLsfd) {
  const ThreeDof system;
  const auto [poles, residues] = system.Modes();
  Frf frf = MakeFrf(3, 2, 1, 100, 0.5, [&](double hz) { return system.H(hz); });
  frf.functions.erase(frf.functions.begin() + 3);  // output 1, input 1
  PlscfResult r;
  ExtractModes(frf, PlscfOptions{}, &r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_EQ(r.blocks.size(), 1u);
  EXPECT_EQ(r.blocks[0].inputs, (std::vector<int>{0, 1}));
  EXPECT_EQ(r.blocks[0].outputs, (std::vector<int>{0, 2}));
  ASSERT_EQ(r.modes.size(), 3u);
  for (size_t p = 0; p < poles.size(); ++p) {
    const ExtractedMode& m = *Nearest(r, poles[p]);
    EXPECT_LT(std::abs(m.eigenvalue - poles[p]), 1e-6 * std::abs(poles[p]));
    EXPECT_TRUE(std::isnan(m.residues(1, 1).real()));
    EXPECT_LT(std::abs(m.residues(1, 0) - residues[p](1, 0)),
              1e-5 * residues[p].cwiseAbs().maxCoeff());
  }
  EXPECT_TRUE(r.real_poles.empty());
  frf.functions.erase(frf.functions.begin() + 4);  // output 2, input 1
  frf.functions.erase(frf.functions.begin() + 1);  // output 0, input 1
  ExtractModes(frf, PlscfOptions{}, &r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_EQ(r.blocks.size(), 1u);
  EXPECT_EQ(r.blocks[0].inputs, (std::vector<int>{0}));
  EXPECT_EQ(r.modes.size(), 3u);
  PlscfOptions bad;
  bad.min_order = 0;
  ExtractModes(frf, bad, &r);
  EXPECT_TRUE(r.status.invalid_input());
  EXPECT_EQ(r.status.message, "orders: need 1 <= min_order <= max_order");
  PlscfOptions high;
  high.max_order = 400;  // more than the 199 lines
  ExtractModes(MakeFrf(3, 2, 1, 100, 0.5, [&](double hz) { return system.H(hz); }), high, &r);
  EXPECT_TRUE(r.status.invalid_input());
  EXPECT_EQ(r.status.message, "199 lines in the band: max_order 400 needs at least 401");
}

// Without an output measured at every input (a drum's layout, contract §9):
// pLSCF fits blocks, and a pole two blocks see is one mode. Split in two
// (the pairs of force 1 and of force 3 share no output) and in three (each
// of three forces measured at two masses, none at all three), every pole
// of the system is found once, with the residues of the functions measured.
TEST(PlscfTest, WithoutAnOutputAtEveryInputBlocksFindEachPoleOnce) {
  const ThreeDof system;
  const auto [poles, residues] = system.Modes();
  const std::vector<std::vector<std::pair<int, int>>> layouts = {
      {{0, 0}, {1, 0}, {2, 2}},                           // (output, force): two parts
      {{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}, {0, 2}}};  // one part, no common output
  const std::vector<size_t> blocks = {2, 3};
  for (size_t k = 0; k < layouts.size(); ++k) {
    Frf frf = MakeFrf(3, 3, 1, 100, 0.5, [&](double hz) { return system.G(hz); });
    std::vector<FrfFunction> kept;
    for (const FrfFunction& f : frf.functions) {
      for (const auto& [o, i] : layouts[k]) {
        if (f.output == o && f.input == i) kept.push_back(f);
      }
    }
    frf.functions = kept;
    PlscfResult r;
    ExtractModes(frf, PlscfOptions{}, &r);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    EXPECT_EQ(r.blocks.size(), blocks[k]) << "layout " << k;
    ASSERT_EQ(r.modes.size(), 3u) << "layout " << k;
    for (size_t p = 0; p < poles.size(); ++p) {
      const ExtractedMode& m = *Nearest(r, poles[p]);
      EXPECT_LT(std::abs(m.eigenvalue - poles[p]), 1e-6 * std::abs(poles[p])) << "layout " << k;
      for (const auto& [o, i] : layouts[k]) {
        EXPECT_LT(std::abs(m.residues(o, i) - residues[p](o, i)), 1e-5 * residues[p].cwiseAbs().maxCoeff())
            << "layout " << k << ", pole " << p << ", output " << o << ", force " << i;
      }
    }
  }
}

// A drum at 10 m/s (no output at every input: the in-plane channels per
// in-plane force, the out-of-plane per lateral force), noise-free: the two
// blocks' poles, refined, are the model's seven at that speed, and its real
// roots in the band (the slip lags, docs/rolling.md §2) are the real poles.
TEST(PlscfTest, ADrumsFrfsAtSpeedGiveTheModelsPolesAtThatSpeed) {
  const double speed = 10;
  const Frf frf = CarTireDrum(speed);
  const ModalSolution truth = RigidRingModel().Solve(ExampleCarTire(), speed);
  ASSERT_TRUE(truth.ok) << truth.error;
  PlscfResult r;
  ExtractModes(frf, PlscfOptions{}, &r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_TRUE(r.refinement.status.ok()) << r.refinement.status.message;
  EXPECT_EQ(r.blocks.size(), 2u);
  EXPECT_EQ(r.modes.size(), truth.modes.size());
  for (const Mode& mode : truth.modes) {
    const ExtractedMode& m = *Nearest(r, mode.eigenvalue);
    const double error = std::abs(m.eigenvalue - mode.eigenvalue) / std::abs(mode.eigenvalue);
    std::printf("%s at %g m/s: %.4f Hz, zeta %.4f: relative error %.2e\n", LabelName(mode.label),
                speed, mode.frequency_hz, mode.damping_ratio, error);
    EXPECT_LT(error, 1e-6) << LabelName(mode.label);
  }
  std::vector<double> lags;
  for (const double root : truth.real_roots) {
    if (-root / (2 * M_PI) >= frf.frequencies_hz.front()) lags.push_back(root);
  }
  ASSERT_EQ(r.real_poles.size(), lags.size());
  std::sort(lags.begin(), lags.end(), std::greater<double>());
  for (size_t j = 0; j < lags.size(); ++j) {
    std::printf("real root %.4f s^-1: found %.6f\n", lags[j], r.real_poles[j]);
    EXPECT_LT(std::abs(r.real_poles[j] / lags[j] - 1), 1e-6);
  }
}

// A sigma of 0 (the public API can pass one; files cannot) is no weight:
// the function counts unweighted, not infinitely, and the poles and LSFD's
// residues stay those of the system.
TEST(PlscfTest, AZeroSigmaIsNoWeight) {
  const ThreeDof system;
  const auto [poles, residues] = system.Modes();
  Frf frf = MakeFrf(3, 2, 1, 100, 0.5, [&](double hz) { return system.H(hz); });
  for (FrfFunction& f : frf.functions) f.sigma.assign(f.h.size(), 1e-6);
  frf.functions[0].sigma[40] = 0;
  PlscfResult r;
  ExtractModes(frf, PlscfOptions{}, &r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_EQ(r.modes.size(), 3u);
  for (size_t p = 0; p < poles.size(); ++p) {
    const ExtractedMode& m = *Nearest(r, poles[p]);
    EXPECT_LT(std::abs(m.eigenvalue - poles[p]), 1e-6 * std::abs(poles[p]));
    EXPECT_LT(std::abs(m.residues(0, 0) - residues[p](0, 0)), 1e-5 * residues[p].cwiseAbs().maxCoeff());
  }
}

}  // namespace
}  // namespace ringid
