// The model against closed forms and the paper's Tables 3-5 (docs/model.md section 12).
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include "model/assignment.h"
#include "model/effects.h"
#include "model/rigid_ring_model.h"
#include "tests/test_support.h"

namespace ringid {

using internal::AssignMaxScore;

namespace {

using testing::PaperIdentified;

// Damped frequency and ratio of a 1-DOF oscillator: w_d = w_n sqrt(1 - zeta^2).
void OneDof(double m, double c, double k, double* hz, double* zeta) {
  const double wn = std::sqrt(k / m);
  *zeta = c / (2 * std::sqrt(k * m));
  *hz = wn * std::sqrt(1 - *zeta * *zeta) / (2 * M_PI);
}

double Mac(const RealShapeVector& a, const RealShapeVector& b) {
  return std::pow(a.dot(b), 2) / (a.squaredNorm() * b.squaredNorm());
}

TEST(ModelTest, DecoupledVerticalModeMatchesClosedForm) {
  const Parameters p = PaperIdentified();
  const ModalSolution s = RigidRingModel().Solve(p);
  ASSERT_TRUE(s.ok) << s.error;
  const Mode* v = s.Find(ModeLabel::kVertical);
  ASSERT_NE(v, nullptr);
  double hz, zeta;
  OneDof(p[Param::m_b], p[Param::c_bz], p[Param::k_bz] + p[Param::k_cz], &hz,
         &zeta);
  EXPECT_NEAR(v->frequency_hz, hz, 1e-9 * hz);
  EXPECT_NEAR(v->damping_ratio, zeta, 1e-12);
}

// Overdamped, the vertical pair is two real roots (-c +- sqrt(c^2 - 4 m k)) / 2m,
// and its label vanishes.
TEST(ModelTest, OverdampedVerticalModeVanishesIntoItsTwoRealRoots) {
  Parameters p = PaperIdentified();
  const double m = p[Param::m_b], k = p[Param::k_bz] + p[Param::k_cz];
  p[Param::c_bz] = 3 * std::sqrt(k * m);  // damping ratio 1.5
  const double c = p[Param::c_bz], root = std::sqrt(c * c - 4 * m * k);
  for (const bool derivatives : {false, true}) {  // closed form; Eigen's solver
    const ModalSolution s = RigidRingModel().Solve(p, 0.0, derivatives);
    ASSERT_TRUE(s.ok) << s.error;
    EXPECT_EQ(s.Find(ModeLabel::kVertical), nullptr);
    EXPECT_EQ(s.vanished, std::vector<ModeLabel>{ModeLabel::kVertical});
    ASSERT_EQ(s.real_roots.size(), 2u);
    EXPECT_NEAR(s.real_roots[0], (-c - root) / (2 * m), 1e-12 * c / m);
    EXPECT_NEAR(s.real_roots[1], (-c + root) / (2 * m), 1e-12 * c / m);
  }
}

TEST(ModelTest, ReproducesTable3) {
  // Table 3, 'Calculation' row, with the task's tolerances.
  const struct { ModeLabel label; double hz, tol; } table3[] = {
      {ModeLabel::kRotationInPhase, 48.9, 0.1},
      {ModeLabel::kRotationAntiPhase, 68.4, 0.1},
      {ModeLabel::kVertical, 72.1, 0.1},
      {ModeLabel::kLongitudinal, 91.6, 0.1},
      {ModeLabel::kCamber, 36.8, 0.3},
      {ModeLabel::kYaw, 36.7, 0.3},
      {ModeLabel::kLateral, 84.5, 0.3}};
  const ModalSolution s = RigidRingModel().Solve(PaperIdentified());
  ASSERT_TRUE(s.ok) << s.error;
  ASSERT_EQ(s.modes.size(), 7u);
  for (const auto& row : table3) {
    const Mode* m = s.Find(row.label);
    ASSERT_NE(m, nullptr) << LabelName(row.label);
    EXPECT_NEAR(m->frequency_hz, row.hz, row.tol) << LabelName(row.label);
  }
}

TEST(ModelTest, Table4And5EigenvectorsUnderThePapersLabels) {
  // Tables 4-5 as printed; the label is the paper's name of each column.
  const struct { ModeLabel label; double v[4]; int n; } tables[] = {
      {ModeLabel::kRotationInPhase, {-4.32e-4, -1.05e-18, -1.35e-3, -9.65e-4}, 4},
      {ModeLabel::kRotationAntiPhase, {-6.98e-6, -1.61e-19, -8.94e-4, 5.18e-4}, 4},
      {ModeLabel::kVertical, {2.49e-19, 9.99e-4, 3.07e-18, 1.17e-18}, 4},
      {ModeLabel::kLongitudinal, {6.98e-5, -3.05e-19, 3.53e-4, -3.09e-4}, 4},
      {ModeLabel::kCamber, {-5.56e-6, -2.16e-3, 1.83e-5}, 3},
      {ModeLabel::kYaw, {-1.22e-17, -4.56e-15, -2.16e-3}, 3},
      {ModeLabel::kLateral, {-6.34e-4, -3.29e-4, 1.72e-4}, 3}};
  const ModalSolution s = RigidRingModel().Solve(PaperIdentified());
  ASSERT_TRUE(s.ok);
  for (const auto& col : tables) {
    const Mode* m = s.Find(col.label);
    ASSERT_NE(m, nullptr);
    RealShapeVector table = RealShapeVector::Zero();
    const int first = col.n == 4 ? 0 : static_cast<int>(Dof::kYb);
    for (int i = 0; i < col.n; ++i) table[first + i] = col.v[i];
    EXPECT_GE(Mac(m->PaperShape(), table), 0.99) << LabelName(col.label);
  }
}

TEST(ModelTest, DominantComponentRuleWouldMislabelTable4) {
  // The trap of docs/model.md section 9: the 91.6 Hz mode is 'longitudinal'
  // although its theta components dominate; its x_b share of kinetic energy
  // is not the largest either. The labels above must not come from such a
  // rule.
  const Parameters p = PaperIdentified();
  const ModalSolution s = RigidRingModel().Solve(p);
  const Mode* longitudinal = s.Find(ModeLabel::kLongitudinal);
  const Mode* in_phase = s.Find(ModeLabel::kRotationInPhase);
  ASSERT_TRUE(longitudinal && in_phase);
  auto kinetic_x = [&](const Mode& m) {
    const double x = std::norm(m.shape[0]) * p[Param::m_b];
    const double ta = std::norm(m.shape[2]) * p[Param::I_ay];
    const double tb = std::norm(m.shape[3]) * p[Param::I_by];
    return x / (x + ta + tb);
  };
  EXPECT_GT(kinetic_x(*in_phase), kinetic_x(*longitudinal));
  EXPECT_GT(std::abs(longitudinal->PaperShape()[2]),
            std::abs(longitudinal->PaperShape()[0]));
}

TEST(ModelTest, YawLabelFollowsTheYawModeThroughTheCamberCrossing) {
  // Yaw is decoupled one way (docs/model.md section 6: S is block
  // triangular): its mode is pure psi_b with the 1-DOF frequency, wherever it
  // sits against camber.
  Parameters p = PaperIdentified();
  for (double k = 900; k <= 3000; k += 50) {  // below ~620 yaw is overdamped
    p[Param::k_bpsi] = k;
    const ModalSolution s = RigidRingModel().Solve(p);
    ASSERT_TRUE(s.ok);
    const Mode* yaw = s.Find(ModeLabel::kYaw);
    ASSERT_NE(yaw, nullptr) << k;
    double hz, zeta;
    OneDof(p[Param::I_bz], p[Param::c_bpsi], k, &hz, &zeta);
    EXPECT_NEAR(yaw->frequency_hz, hz, 1e-8 * hz) << "k_bpsi " << k;
    const Mode* camber = s.Find(ModeLabel::kCamber);
    ASSERT_NE(camber, nullptr);
    EXPECT_LT(std::abs(camber->shape[static_cast<int>(Dof::kYb)]), 0.05);
  }
}

TEST(ModelTest, VerticalLabelFollowsTheVerticalModeAcrossInPlaneModes) {
  Parameters p = PaperIdentified();
  for (double k_cz = 2e4; k_cz <= 1.6e6; k_cz *= 1.15) {
    p[Param::k_cz] = k_cz;
    const ModalSolution s = RigidRingModel().Solve(p);
    ASSERT_TRUE(s.ok);
    const Mode* v = s.Find(ModeLabel::kVertical);
    ASSERT_NE(v, nullptr);
    double hz, zeta;
    OneDof(p[Param::m_b], p[Param::c_bz], p[Param::k_bz] + k_cz, &hz, &zeta);
    EXPECT_NEAR(v->frequency_hz, hz, 1e-8 * hz) << "k_cz " << k_cz;
    // The other in-plane labels do not move with k_cz.
    const Mode* l = s.Find(ModeLabel::kLongitudinal);
    ASSERT_NE(l, nullptr);
    EXPECT_NEAR(l->frequency_hz, 91.6, 0.1);
  }
}

TEST(ModelTest, EveryEffectAtZeroIsTheBaselineAndApproachesItContinuously) {
  Parameters p = PaperIdentified();
  p[Param::m_a] = 10;
  const ModalSolution base = RigidRingModel().Solve(p);
  ASSERT_TRUE(base.ok);
  for (const Effect* e : EffectCatalogue()) {
    const RigidRingModel model({e});
    const ModalSolution zero = model.Solve(p);
    ASSERT_TRUE(zero.ok) << e->name();
    ASSERT_EQ(zero.modes.size(), base.modes.size()) << e->name();
    for (size_t i = 0; i < base.modes.size(); ++i) {
      EXPECT_EQ(zero.modes[i].label, base.modes[i].label) << e->name();
      EXPECT_DOUBLE_EQ(zero.modes[i].frequency_hz, base.modes[i].frequency_hz);
    }
    // A tiny effect moves no frequency by more than a tiny amount.
    Parameters q = p;
    for (Param x : e->parameters()) {
      if (x == Param::m_a) continue;
      q[x] = x == Param::s_h ? 1e-12 : x == Param::dm ? 1e-9 : 1e-3;
    }
    const ModalSolution tiny = model.Solve(q);
    ASSERT_TRUE(tiny.ok) << e->name();
    for (const Mode& m : base.modes) {
      const Mode* t = tiny.Find(m.label);
      ASSERT_NE(t, nullptr) << e->name() << " " << LabelName(m.label);
      EXPECT_NEAR(t->frequency_hz, m.frequency_hz, 1e-3) << e->name();
    }
  }
}

TEST(ModelTest, LugCouplingMakesOneSevenDofSystemAndKeepsAllLabels) {
  Parameters p = PaperIdentified();
  p[Param::k_xy] = 1e5;
  const ModalSolution s = RigidRingModel({FindEffect("lug_coupling")}).Solve(p);
  ASSERT_TRUE(s.ok);
  int coupled = 0;
  for (const Mode& m : s.modes) {
    if (std::abs(m.shape[static_cast<int>(Dof::kXb)]) > 1e-3 &&
        std::abs(m.shape[static_cast<int>(Dof::kYb)]) > 1e-3) {
      ++coupled;
    }
  }
  EXPECT_GE(coupled, 2);
  for (int l = 0; l < 7; ++l) {
    EXPECT_NE(s.Find(static_cast<ModeLabel>(l)), nullptr)
        << LabelName(static_cast<ModeLabel>(l));
  }
}

TEST(ModelTest, HubComplianceAddsHubModes) {
  Parameters p = PaperIdentified();
  p[Param::m_a] = 20;
  p[Param::s_h] = 1e-7;
  const ModalSolution s =
      RigidRingModel({FindEffect("hub_compliance")}).Solve(p);
  ASSERT_TRUE(s.ok) << s.error;
  EXPECT_EQ(s.modes.size() + s.vanished.size(), 10u);
  // A hub of 20 kg on 1e7 N/m springs sits near sqrt(k/m)/2pi = 112 Hz.
  const Mode* hub = s.Find(ModeLabel::kHubVertical);
  ASSERT_NE(hub, nullptr);
  EXPECT_GT(hub->frequency_hz, 90);
  EXPECT_LT(hub->frequency_hz, 140);
}

// Mode::energy is |w^T K_label v| / total with w the left vector of
// lambda^2 M + lambda C + K. Independently: the left eigenvectors of the whole
// active system's state matrix, from Eigen's solver on A^T, w = M^-T y2.
void ExpectEnergiesFromLeftEigenvectors(const RigidRingModel& model, const Parameters& p) {
  const MechanicalSystem s = model.Assemble(p);
  const ModalSolution solution = model.Solve(p);
  ASSERT_TRUE(solution.ok) << solution.error;
  std::vector<int> on;
  for (int i = 0; i < kNumDofs; ++i) {
    if (s.active(static_cast<Dof>(i))) on.push_back(i);
  }
  const int n = static_cast<int>(on.size());
  Eigen::MatrixXd M(n, n), C(n, n), K(n, n);
  for (int a = 0; a < n; ++a) {
    for (int b = 0; b < n; ++b) {
      M(a, b) = s.M()(on[a], on[b]);
      C(a, b) = s.C()(on[a], on[b]);
      K(a, b) = s.K()(on[a], on[b]);
    }
  }
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n).setIdentity();
  A.bottomLeftCorner(n, n) = -M.inverse() * K;
  A.bottomRightCorner(n, n) = -M.inverse() * C;
  const Eigen::EigenSolver<Eigen::MatrixXd> left(A.transpose());
  for (const Mode& mode : solution.modes) {
    int j = 0;
    for (int i = 1; i < 2 * n; ++i) {
      if (std::abs(left.eigenvalues()[i] - mode.eigenvalue) <
          std::abs(left.eigenvalues()[j] - mode.eigenvalue)) {
        j = i;
      }
    }
    ASSERT_LT(std::abs(left.eigenvalues()[j] - mode.eigenvalue), 1e-6 * std::abs(mode.eigenvalue));
    const Eigen::VectorXcd w =
        M.inverse().transpose().cast<std::complex<double>>() * left.eigenvectors().col(j).tail(n);
    Eigen::VectorXcd v(n);
    for (int a = 0; a < n; ++a) v[a] = mode.shape[on[a]];
    const auto bilinear = [&](const MechanicalSystem::Matrix& k) {
      std::complex<double> sum = 0;
      for (int a = 0; a < n; ++a) {
        for (int b = 0; b < n; ++b) sum += w[a] * k(on[a], on[b]) * v[b];
      }
      return sum;
    };
    std::complex<double> rest = bilinear(s.K());
    std::array<double, kNumLabels> expected{};
    double total = 0;
    for (int l = 0; l < kNumLabels; ++l) {
      const std::complex<double> e = bilinear(s.K_label(static_cast<ModeLabel>(l)));
      expected[l] = std::abs(e);
      total += std::abs(e);
      rest -= e;
    }
    total += std::abs(rest);
    for (int l = 0; l < kNumLabels; ++l) {
      EXPECT_NEAR(mode.energy[l], expected[l] / total, 1e-8)
          << LabelName(mode.label) << " share of " << LabelName(static_cast<ModeLabel>(l));
    }
  }
}

// The out-of-plane block is unsymmetric (the trail t_0), so its left vectors
// differ from its right ones; hub compliance makes blocks of more than three
// degrees of freedom; lug coupling joins the planes.
TEST(ModelTest, EnergySharesUseTheLeftEigenvectorsOfEveryBlock) {
  Parameters p = PaperIdentified();
  p[Param::m_a] = 20;
  ExpectEnergiesFromLeftEigenvectors(RigidRingModel(), p);
  for (const Effect* e : EffectCatalogue()) {
    SCOPED_TRACE(e->name());
    Parameters q = p;
    q[Param::s_h] = 1e-7;
    q[Param::k_xy] = 1e5;
    ExpectEnergiesFromLeftEigenvectors(RigidRingModel({e}), q);
  }
}

// Expects the modes of `model` at p to be the same without derivatives
// (shapes from the pencil's adjugate on blocks of up to three degrees of
// freedom) as with them (Eigen's eigenvectors), each shape a null vector of
// lambda^2 M + lambda C + K. Counts the modes whose shapes differ from
// Eigen's in any bit: those the adjugate gave.
void ExpectShapesOfThePencil(const RigidRingModel& model, const Parameters& p, int* from_adjugate) {
  const MechanicalSystem s = model.Assemble(p);
  const ModalSolution values_only = model.Solve(p);
  const ModalSolution with_vectors = model.Solve(p, 0.0, /*derivatives=*/true);
  ASSERT_TRUE(values_only.ok && with_vectors.ok) << values_only.error << with_vectors.error;
  ASSERT_EQ(values_only.modes.size(), with_vectors.modes.size());
  for (size_t i = 0; i < values_only.modes.size(); ++i) {
    const Mode& a = values_only.modes[i];
    const Mode& b = with_vectors.modes[i];
    SCOPED_TRACE(LabelName(a.label));
    EXPECT_EQ(a.label, b.label);
    EXPECT_LT(std::abs(a.eigenvalue - b.eigenvalue), 1e-12 * std::abs(b.eigenvalue));
    EXPECT_LT((a.shape - b.shape).norm(), 1e-9);
    *from_adjugate += a.shape != b.shape;
    const std::complex<double> l = a.eigenvalue;
    ShapeVector r = (l * l * s.M().cast<std::complex<double>>() +
                     l * s.C().cast<std::complex<double>>() +
                     s.K().cast<std::complex<double>>()) * a.shape;
    for (int d = 0; d < kNumDofs; ++d) {
      if (!s.active(static_cast<Dof>(d))) r[d] = 0;  // the hub's reactions
    }
    const double size = (std::norm(l) * s.M().cwiseAbs() + std::abs(l) * s.C().cwiseAbs() +
                         s.K().cwiseAbs()).norm();
    EXPECT_LT(r.norm(), 1e-12 * size);
  }
}

// Without derivatives, a standing block of up to three degrees of freedom
// takes its shapes from the adjugate of its pencil, not from Eigen's
// eigenvectors (docs/model.md §8): at the paper's point, 19 random points,
// and with each effect (hub compliance makes a block of two, z_b and z_a;
// lug coupling one of seven, which keeps Eigen's vectors).
TEST(ModelTest, ShapesFromThePencilAgreeWithTheStateMatrixEigenvectors) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> factor(0.5, 2.0);
  int from_adjugate = 0, modes = 0;
  for (int trial = 0; trial < 20; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    Parameters p = PaperIdentified();
    if (trial > 0) {
      for (int i = 0; i < kNumParams; ++i) p[static_cast<Param>(i)] *= factor(rng);
    }
    ExpectShapesOfThePencil(RigidRingModel(), p, &from_adjugate);
    modes += 7;
  }
  // Every mode but z_b's (one degree of freedom: its shape is 1) came from
  // the adjugate, and so differs from Eigen's in the last bits.
  EXPECT_GE(from_adjugate, modes * 5 / 7);
  Parameters p = PaperIdentified();
  p[Param::m_a] = 20;
  p[Param::s_h] = 1e-7;
  p[Param::k_xy] = 1e5;
  for (const Effect* e : EffectCatalogue()) {
    SCOPED_TRACE(e->name());
    int ignored = 0;
    ExpectShapesOfThePencil(RigidRingModel({e}), p, &ignored);
  }
  const RigidRingModel hub({FindEffect("hub_compliance")});
  int two_dof_modes = 0;
  for (const Mode& mode : hub.Solve(p).modes) {
    two_dof_modes += mode.shape[static_cast<int>(Dof::kZb)] != 0.0 &&
                     mode.shape[static_cast<int>(Dof::kZa)] != 0.0 &&
                     (mode.shape.array() != 0.0).count() == 2;
  }
  EXPECT_EQ(two_dof_modes, 2);  // the block of two was solved
}

// Equal oscillators on y_b, gamma_b and psi_b joined by one spring: K = a I +
// b u w^T has the eigenvalue a twice, with two vectors, and the adjugate of
// the pencil there is rounding. The block is solved again with Eigen's
// vectors: two independent shapes for the double root, each a null vector of
// the pencil; symmetric (w = u) and not (the left vectors then come from V^-1).
TEST(ModelTest, ARepeatedEigenvalueWithTwoVectorsTakesEigensVectors) {
  const double a = 4e5, b = 1e5;
  const Dof block[3] = {Dof::kYb, Dof::kGammaB, Dof::kPsiB};
  const ModeLabel owner[3] = {ModeLabel::kLateral, ModeLabel::kCamber, ModeLabel::kYaw};
  for (const Eigen::Vector3d w : {Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(1, 2, 0.5)}) {
    SCOPED_TRACE(w.transpose());
    const Eigen::Vector3d u(1, 1, 1);
    MechanicalSystem s;
    for (int i = 0; i < kNumDofs; ++i) {
      const Dof dof = static_cast<Dof>(i);
      if (!s.active(dof)) continue;
      s.AddMass(dof, 1.0);
      const auto in = std::find(std::begin(block), std::end(block), dof);
      if (in == std::end(block)) {
        s.AddSpring(std::nullopt, a * (1 + 0.1 * i), {{dof, 1}});
      } else {
        s.AddSpring(owner[in - std::begin(block)], a, {{dof, 1}});
      }
    }
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) s.AddStiffness(std::nullopt, block[r], block[c], b * u[r] * w[c]);
    }
    const ModalSolution solution = SolveModes(s);
    ASSERT_TRUE(solution.ok) << solution.error;
    std::vector<Eigen::Vector3cd> repeated;
    int single = 0;
    for (const Mode& mode : solution.modes) {
      Eigen::Vector3cd v;
      for (int r = 0; r < 3; ++r) v[r] = mode.shape[static_cast<int>(block[r])];
      if (v.norm() == 0) continue;  // another block
      ASSERT_TRUE(mode.shape.allFinite());
      const double w2 = std::pow(2 * M_PI * mode.frequency_hz, 2);
      if (std::abs(w2 - a) < 1e-6 * a) repeated.push_back(v);
      single += std::abs(w2 - (a + b * u.dot(w))) < 1e-6 * a;
      const ShapeVector r = (s.K().cast<std::complex<double>>() -
                             w2 * s.M().cast<std::complex<double>>()) * mode.shape;
      EXPECT_LT(r.norm(), 1e-8 * a * mode.shape.norm());
      double shares = 0;
      for (double e : mode.energy) {
        EXPECT_TRUE(std::isfinite(e) && e >= 0);
        shares += e;
      }
      EXPECT_LE(shares, 1 + 1e-12);
    }
    ASSERT_EQ(repeated.size(), 2u);
    EXPECT_EQ(single, 1);
    const double mac = std::norm(repeated[0].dot(repeated[1])) /
                       (repeated[0].squaredNorm() * repeated[1].squaredNorm());
    EXPECT_LT(mac, 0.99);  // two shapes, not one twice
  }
}

// The balanced velocity unit is the power of two nearest sqrt(K/M): exact in
// binary, so balancing rounds nothing.
TEST(ModelTest, BalancingFrequencyIsThePowerOfTwoNearestTheNaturalFrequency) {
  EXPECT_EQ(BalancingFrequency(2000.0 * 2000.0), 2048.0);
  EXPECT_EQ(BalancingFrequency(1400.0 * 1400.0), 1024.0);  // log2 1400 = 10.45
  EXPECT_EQ(BalancingFrequency(1500.0 * 1500.0), 2048.0);  // log2 1500 = 10.55
  EXPECT_EQ(BalancingFrequency(0.0), 1.0);
  EXPECT_EQ(BalancingFrequency(std::numeric_limits<double>::infinity()), 1.0);
  EXPECT_EQ(BalancingFrequency(std::nan("")), 1.0);
}

TEST(ModelTest, BadParametersGiveAnErrorNotAMode) {
  Parameters p = PaperIdentified();
  p[Param::m_b] = 0;
  ModalSolution s = RigidRingModel().Solve(p);
  EXPECT_FALSE(s.ok);
  EXPECT_NE(s.error.find("mass"), std::string::npos);
  p = PaperIdentified();
  p[Param::K_cx] = std::nan("");
  s = RigidRingModel().Solve(p);
  EXPECT_FALSE(s.ok);
  EXPECT_TRUE(s.modes.empty());
}

TEST(AssignmentTest, MatchesBruteForceOverPermutations) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const int rows = 1 + trial % 5, cols = rows + trial % 3;
    Eigen::MatrixXd score(rows, cols);
    for (int i = 0; i < rows; ++i)
      for (int j = 0; j < cols; ++j) score(i, j) = u(rng);
    // Half the trials with a dominant column per row (the short cut's case).
    if (trial % 2) {
      for (int i = 0; i < rows; ++i) score(i, (i + trial) % cols) += 2;
    }
    const std::vector<int> pick = AssignMaxScore(score);
    double got = 0;
    for (int i = 0; i < rows; ++i) got += score(i, pick[i]);
    std::vector<int> perm(cols);
    std::iota(perm.begin(), perm.end(), 0);
    double best = -1e300;
    do {
      double v = 0;
      for (int i = 0; i < rows; ++i) v += score(i, perm[i]);
      best = std::max(best, v);
    } while (std::next_permutation(perm.begin(), perm.end()));
    EXPECT_NEAR(got, best, 1e-12);
  }
}

}  // namespace
}  // namespace ringid
