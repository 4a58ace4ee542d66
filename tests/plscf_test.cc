// pLSCF, its stabilisation diagram, the physical poles and LSFD
// (estimation/plscf.h, issue 37 step 1) against closed forms: a 3-DOF
// system written here (H = (K + iωC - ω²M)^-1, its poles and residues from
// its own eigenproblem), the car tire's hammer test against the model's
// modal solution, and two close, damped modes with noise.
#include "estimation/plscf.h"

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

namespace ringid {
namespace {

using cd = std::complex<double>;

// An Frf of `outputs` x `inputs` (displacements, every pair) whose values
// are h(hz) at lines low..high every step, sigma `relative` of |H| (floored
// as contract §9's FrfSigma) or none.
Frf MakeFrf(int outputs, int inputs, double low, double high, double step,
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

// Adds circular noise of sd `relative` x FrfSigma to each value, and sets sigma so.
void AddNoise(double relative, std::mt19937_64* rng, Frf* frf) {
  std::normal_distribution<double> normal;
  for (FrfFunction& f : frf->functions) {
    double peak = 0;
    for (const cd& h : f.h) peak = std::max(peak, std::abs(h));
    f.sigma.clear();
    for (cd& h : f.h) {
      const double sigma = FrfSigma(relative, h, peak);
      f.sigma.push_back(sigma);
      h += cd(sigma * normal(*rng), sigma * normal(*rng));
    }
  }
}

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
  // Receptance at the three masses per force on masses 1 and 3.
  Eigen::MatrixXcd H(double hz) const {
    const double w = 2 * M_PI * hz;
    const Eigen::Matrix3cd D = (K - w * w * M).cast<cd>() + cd(0, w) * C.cast<cd>();
    Eigen::MatrixXcd g = D.inverse();
    Eigen::MatrixXcd h(3, 2);
    h << g.col(0), g.col(2);
    return h;
  }
  // The state-space eigenproblem [0 I; -K -C] v = λ [I 0; 0 M] v: its
  // eigenvalues with Im > 0, and each one's residue matrix of H (3 x 3,
  // columns per force), from the standard form A = B^-1 [0 I; -K -C]:
  // H(s) = [I 0] (sI - A)^-1 [0; M^-1] = sum_r V_r W_r [0; M^-1] / (s - λ_r).
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
        if (std::abs(es.eigenvalues()(q) - lambda(r)) < std::abs(es.eigenvalues()(e) - lambda(r))) e = q;
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
  std::vector<cd> poles;
  std::vector<Eigen::Matrix3cd> residues;
  system.Modes(&poles, &residues);
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

// The car tire's standing hammer test (datasets/synthetic.h: 4 blows x 7
// accelerometers), noise-free from the model's H.
Frf CarTireHammer(double low_hz = 5, double high_hz = 250, double step_hz = 0.5) {
  Frf frf = HammerTest(0.31, low_hz, high_hz, step_hz);
  ResponseRequest request;
  for (const FrfInput& in : frf.inputs) {
    request.inputs.push_back({std::nullopt, Coordinates(in.coordinates.begin(), in.coordinates.end())});
  }
  for (const FrfOutput& out : frf.outputs) {
    request.outputs.push_back({std::nullopt, Coordinates(out.coordinates.begin(), out.coordinates.end()),
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

TEST(PlscfTest, ANoiseFreeHammerTestGivesTheModelsPoles) {
  const Frf frf = CarTireHammer();
  const ModalSolution truth = RigidRingModel().Solve(ExampleCarTire());
  ASSERT_TRUE(truth.ok) << truth.error;
  PlscfOptions o;
  PlscfResult r;
  const auto start = std::chrono::steady_clock::now();
  ExtractModes(frf, o, &r);
  std::printf("hammer test, 28 FRFs x %zu lines, orders 1..%d: %.3f s\n", frf.frequencies_hz.size(),
              o.max_order, Seconds(start));
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  int in_band = 0;
  for (const Mode& mode : truth.modes) {
    if (mode.frequency_hz < 5 || mode.frequency_hz > 250) continue;
    ++in_band;
    const ExtractedMode& m = *Nearest(r, mode.eigenvalue);
    const double error = std::abs(m.eigenvalue - mode.eigenvalue) / std::abs(mode.eigenvalue);
    std::printf("%s %.4f Hz, zeta %.4f: relative error %.2e (order %d, %d stable orders)\n",
                LabelName(mode.label), mode.frequency_hz, mode.damping_ratio, error, m.order,
                m.stable_orders);
    EXPECT_LT(error, 1e-6) << LabelName(mode.label);
  }
  EXPECT_EQ(in_band, 7);
  EXPECT_EQ(static_cast<int>(r.modes.size()), in_band);
}

}  // namespace
}  // namespace ringid
