// The frequency response from the lug forces to the axle (model/
// forced_response.h) against truths it does not share code with: the closed
// form of the one-degree-of-freedom vertical block, the static shares of a
// standing tire, a time integration of eqs. (R6)-(R7) driven by a sinusoid
// with the outputs written from contract §8's formulas, and the symmetry of
// the standing in-plane receptance that rolling breaks.
#include <cmath>
#include <complex>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "datasets/synthetic.h"
#include "model/campbell.h"
#include "model/effects.h"
#include "model/forced_response.h"
#include "model/frequency_response.h"
#include "model/rigid_ring_model.h"
#include "tests/test_support.h"

namespace ringid {
namespace {

using P = Param;

Complex At(const AxleResponseMatrix& H, AxleChannel c, LugForce f) {
  return H(static_cast<int>(c), static_cast<int>(f));
}

AxleResponseMatrix Response(const RigidRingModel& model, const Parameters& p, double speed,
                            double hz) {
  AxleResponseMatrix H;
  std::string why;
  EXPECT_TRUE(AxleResponse(model, p, speed, hz, &H, &why)) << why;
  return H;
}

// Standing, z_b is a block of its own: m z'' + c_bz z' + (k_bz + k_cz) z = F_z,
// and the axle carries k_bz z + c_bz z'; an anisotropic sidewall adds dk_bz
// to the spring and to what the axle carries.
TEST(ForcedResponseTest, TheVerticalChannelStandingIsTheClosedFormOfOneDegreeOfFreedom) {
  Parameters anisotropic = ExampleCarTire();
  anisotropic[P::dk_bz] = 0.2 * anisotropic[P::k_bz];
  const std::pair<RigidRingModel, Parameters> cases[] = {
      {RigidRingModel(), ExampleCarTire()},
      {RigidRingModel(), testing::PaperIdentified()},
      {RigidRingModel({FindEffect("anisotropic_sidewall")}), anisotropic}};
  for (const auto& [model, p] : cases) {
    const double m = p[P::m_b], c = p[P::c_bz], k = p[P::k_bz] + p[P::dk_bz], kc = p[P::k_cz];
    const double resonance = std::sqrt((k + kc) / m) / (2 * M_PI);
    for (double hz : {0.5, 10.0, 0.9 * resonance, resonance, 1.1 * resonance, 400.0}) {
      const double w = 2 * M_PI * hz;
      const Complex expected = Complex(k, w * c) / Complex(k + kc - m * w * w, w * c);
      const Complex got = At(Response(model, p, 0, hz), AxleChannel::kForceZ, LugForce::kFz);
      EXPECT_LT(std::abs(got - expected), 1e-10 * std::abs(expected)) << hz << " Hz";
    }
  }
}

// Slowly, F_z shares itself between the sidewall and the contact springs,
// k_bz / (k_bz + k_cz) to the axle; F_x at the contact point is reacted by the
// contact where it acts (the rim turns freely), so none reaches the axle.
// With a compliant hub the sidewall and the hub's spring 1 / s_h are in series.
TEST(ForcedResponseTest, SlowlyTheAxleCarriesTheStaticSharesOfTheLugForces) {
  Parameters p = ExampleCarTire();
  const RigidRingModel model;
  const double k = p[P::k_bz], kc = p[P::k_cz];
  double previous_fx = INFINITY;
  for (double hz : {1e-1, 1e-2, 1e-3}) {
    const AxleResponseMatrix H = Response(model, p, 0, hz);
    EXPECT_NEAR(std::abs(At(H, AxleChannel::kForceZ, LugForce::kFz)), k / (k + kc), 1e-3);
    const double fx = std::abs(At(H, AxleChannel::kForceX, LugForce::kFx));
    EXPECT_LT(fx, previous_fx / 5) << hz;  // vanishes with the frequency
    previous_fx = fx;
  }
  EXPECT_LT(previous_fx, 1e-4);
  const RigidRingModel hub({FindEffect("hub_compliance")});
  p[P::s_h] = 2e-7;
  p[P::m_a] = 15;
  const double series = 1 / (1 / k + p[P::s_h]);
  const AxleResponseMatrix H = Response(hub, p, 0, 1e-3);
  EXPECT_NEAR(std::abs(At(H, AxleChannel::kForceZ, LugForce::kFz)), series / (series + kc), 1e-5);
}

// The state x = [q; q'; zeta] of eqs. (R6)-(R7) integrated by RK4 under a
// cosine lug force; the axle outputs written from contract §8's formulas.
struct Simulation {
  MechanicalSystem s;
  std::vector<int> dofs;
  Eigen::MatrixXd M_inv, C, K0, F, Dv, E;
  Eigen::VectorXd sigma, stiffness, b;
  double V;
};

Eigen::VectorXd Rate(const Simulation& sim, const Eigen::VectorXd& x, double force) {
  const int k = static_cast<int>(sim.dofs.size()), m = static_cast<int>(sim.sigma.size());
  const Eigen::VectorXd q = x.head(k), v = x.segment(k, k), zeta = x.tail(m);
  Eigen::VectorXd dx(2 * k + m);
  dx.head(k) = v;
  dx.segment(k, k) =
      sim.M_inv * (sim.b * force - sim.C * v - sim.K0 * q + sim.F * sim.stiffness.cwiseProduct(zeta));
  for (int j = 0; j < m; ++j) {
    dx(2 * k + j) = (-sim.V * zeta(j) - sim.Dv.col(j).dot(v) + sim.V * sim.E.col(j).dot(q)) / sim.sigma(j);
  }
  return dx;
}

TEST(ForcedResponseTest, RollingTheSteadyStateOfATimeIntegrationIsTheResponse) {
  const Parameters p = ExampleCarTire();
  const RigidRingModel model;
  const double V = 10, hz = 35, w = 2 * M_PI * hz, omega = V / p[P::r_e0];
  Simulation sim{model.Assemble(p, V)};
  sim.dofs = ActiveDofs(sim.s);
  sim.V = V;
  const int k = static_cast<int>(sim.dofs.size()), m = static_cast<int>(sim.s.lags().size());
  auto index = [&](Dof d) {
    for (int a = 0; a < k; ++a) {
      if (sim.dofs[a] == static_cast<int>(d)) return a;
    }
    return -1;
  };
  sim.M_inv = Eigen::MatrixXd::Zero(k, k);
  sim.C.resize(k, k);
  sim.K0.resize(k, k);
  for (int a = 0; a < k; ++a) {
    sim.M_inv(a, a) = 1 / sim.s.M()(sim.dofs[a], sim.dofs[a]);
    for (int c = 0; c < k; ++c) {
      sim.C(a, c) = sim.s.C()(sim.dofs[a], sim.dofs[c]);
      sim.K0(a, c) = sim.s.K()(sim.dofs[a], sim.dofs[c]);
    }
  }
  sim.F = sim.Dv = sim.E = Eigen::MatrixXd::Zero(k, m);
  sim.sigma.resize(m);
  sim.stiffness.resize(m);
  for (int j = 0; j < m; ++j) {
    const auto& lag = sim.s.lags()[j];
    sim.sigma(j) = lag.relaxation_length;
    sim.stiffness(j) = lag.stiffness;
    for (const auto& [d, c] : lag.force) sim.F(index(d), j) = c;
    for (const auto& [d, c] : lag.velocity) sim.Dv(index(d), j) = c;
    for (const auto& [d, c] : lag.heading) sim.E(index(d), j) = c;
  }
  sim.K0 -= sim.F * (sim.stiffness.cwiseQuotient(sim.sigma)).asDiagonal() * sim.Dv.transpose();
  const AxleResponseMatrix H = Response(model, p, V, hz);
  for (LugForce force : {LugForce::kFx, LugForce::kFz, LugForce::kFy}) {
    sim.b = LugForceColumns(p).col(static_cast<int>(force));
    sim.b = Eigen::VectorXd(sim.b);
    Eigen::VectorXd b(k);
    for (int a = 0; a < k; ++a) b(a) = sim.b(sim.dofs[a]);
    sim.b = b;
    Eigen::VectorXd x = Eigen::VectorXd::Zero(2 * k + m);
    const double dt = 1e-5, settle = 1.5, periods = 20, T = periods / hz;
    const int steps = static_cast<int>(std::round((settle + T) / dt));
    const int first = static_cast<int>(std::round(settle / dt));
    std::vector<Complex> Y(kNumAxleChannels, 0.0);
    for (int n = 0; n < steps; ++n) {
      const double t = n * dt;
      if (n >= first) {  // Fourier coefficient at w by the trapezoid over whole periods
        const Eigen::VectorXd q = x.head(k), v = x.segment(k, k);
        auto Q = [&](Dof d) { return index(d) < 0 ? 0.0 : q(index(d)); };
        auto Qd = [&](Dof d) { return index(d) < 0 ? 0.0 : v(index(d)); };
        const double y[kNumAxleChannels] = {
            p[P::k_bx] * Q(Dof::kXb) + p[P::c_bx] * Qd(Dof::kXb) + p[P::c_bz] * omega * Q(Dof::kZb),
            p[P::k_bz] * Q(Dof::kZb) + p[P::c_bz] * Qd(Dof::kZb) - p[P::c_bx] * omega * Q(Dof::kXb),
            p[P::k_by] * Q(Dof::kYb) + p[P::c_by] * Qd(Dof::kYb),
            p[P::k_bgamma] * Q(Dof::kGammaB) + p[P::c_bgamma] * Qd(Dof::kGammaB) +
                p[P::c_bpsi] * omega * Q(Dof::kPsiB),
            p[P::k_bpsi] * Q(Dof::kPsiB) + p[P::c_bpsi] * Qd(Dof::kPsiB) -
                p[P::c_bgamma] * omega * Q(Dof::kGammaB)};
        const double weight = (n == first || n == steps - 1) ? 0.5 : 1.0;
        for (int c = 0; c < kNumAxleChannels; ++c) {
          Y[c] += weight * dt * y[c] * std::exp(Complex(0, -w * t)) * (2 / T);
        }
      }
      const Eigen::VectorXd k1 = Rate(sim, x, std::cos(w * t));
      const Eigen::VectorXd k2 = Rate(sim, x + dt / 2 * k1, std::cos(w * (t + dt / 2)));
      const Eigen::VectorXd k3 = Rate(sim, x + dt / 2 * k2, std::cos(w * (t + dt / 2)));
      const Eigen::VectorXd k4 = Rate(sim, x + dt * k3, std::cos(w * (t + dt)));
      x += dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    double scale = 0;
    for (int c = 0; c < kNumAxleChannels; ++c) scale = std::max(scale, std::abs(H(c, static_cast<int>(force))));
    ASSERT_GT(scale, 1e-3);
    for (int c = 0; c < kNumAxleChannels; ++c) {
      EXPECT_LT(std::abs(Y[c] - H(c, static_cast<int>(force))), 2e-3 * scale)
          << ToString(force) << " -> " << ToString(static_cast<AxleChannel>(c)) << ": integrated "
          << Y[c] << ", response " << H(c, static_cast<int>(force));
    }
  }
}

// Standing, the in-plane matrices are symmetric and so is the receptance;
// the rotating terms (R3)-(R5) and the slip lags break it at speed.
TEST(ForcedResponseTest, TheInPlaneReceptanceIsSymmetricStandingAndNotRolling) {
  const Parameters p = ExampleCarTire();
  const RigidRingModel model;
  // Unit generalised forces in, displacements out, on x_b, z_b, theta_a, theta_b.
  ResponseRequest request;
  request.frequencies_hz = {20.0, 60.0, 90.0};
  const Dof in_plane[] = {Dof::kXb, Dof::kZb, Dof::kThetaA, Dof::kThetaB};
  for (int a = 0; a < 4; ++a) {
    request.inputs.push_back({std::nullopt, {{in_plane[a], 1.0}}});
    request.outputs.push_back({std::nullopt, {{in_plane[a], 1.0}}, 0});
    for (int b = 0; b < 4; ++b) request.pairs.push_back({a, b});
  }
  for (double speed : {0.0, 15.0}) {
    const ResponseResult r = FrequencyResponse(model, p, speed, request);
    ASSERT_TRUE(r.ok) << r.error;
    for (int l = 0; l < 3; ++l) {
      Eigen::MatrixXcd R(4, 4);
      for (int f = 0; f < 16; ++f) R(f / 4, f % 4) = r.H(l, f);
      const double asymmetry = (R - R.transpose()).norm() / R.norm();
      if (speed == 0) {
        EXPECT_LT(asymmetry, 1e-12) << request.frequencies_hz[l];
      } else {
        EXPECT_GT(asymmetry, 1e-3) << request.frequencies_hz[l];
      }
    }
  }
}

// Each critical speed is where the order's line meets the mode (to 1e-5 of
// its frequency), and a scan of 2001 speeds finds the same crossings as the
// 21 speeds given (none lies so close to another that the coarse grid
// misses a pair).
TEST(CampbellTest, CriticalSpeedsAreWhereALugOrderMeetsAModeAndNoneIsMissed) {
  const Parameters p = ExampleCarTire();
  const RigidRingModel model;
  const int lugs = 20;
  std::vector<double> coarse, fine;
  for (int i = 0; i <= 20; ++i) coarse.push_back(4.0 + 0.8 * i);  // 4-20 m/s
  for (int i = 0; i <= 2000; ++i) fine.push_back(4.0 + 0.008 * i);
  const std::vector<CriticalSpeed> found = CriticalSpeeds(model, p, lugs, coarse, kMaxOrders);
  ASSERT_GE(found.size(), 5u);
  for (const CriticalSpeed& c : found) {
    const double order_hz = LugOrderHz(c.order, lugs, p[P::r_e0], c.speed_m_s);
    EXPECT_NEAR(order_hz, c.frequency_hz, 1e-5 * c.frequency_hz) << ToString(c.label);
    const ModalSolution there = model.Solve(p, c.speed_m_s);
    const Mode* m = there.Find(c.label);
    ASSERT_NE(m, nullptr);
    EXPECT_NEAR(m->frequency_hz, c.frequency_hz, 1e-9 * c.frequency_hz);
  }
  std::vector<ModalSolution> at;
  for (double v : fine) at.push_back(model.Solve(p, v));
  int crossings = 0;
  for (int k = 1; k <= 10; ++k) {
    for (int l = 0; l < kNumLabels; ++l) {
      for (size_t i = 0; i + 1 < fine.size(); ++i) {
        const Mode* a = at[i].Find(static_cast<ModeLabel>(l));
        const Mode* b = at[i + 1].Find(static_cast<ModeLabel>(l));
        if (!a || !b) continue;
        const double ga = a->frequency_hz - LugOrderHz(k, lugs, p[P::r_e0], fine[i]);
        const double gb = b->frequency_hz - LugOrderHz(k, lugs, p[P::r_e0], fine[i + 1]);
        crossings += (ga > 0) != (gb > 0);
      }
    }
  }
  EXPECT_EQ(static_cast<int>(found.size()), crossings);
}

}  // namespace
}  // namespace ringid
