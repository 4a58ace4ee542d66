// The rolling model of docs/rolling.md, checked against physics rather than
// against its own transcription.
#include <algorithm>
#include <cmath>
#include <complex>
#include <map>
#include <random>

#include <gtest/gtest.h>

#include "datasets/dataset.h"
#include "model/rigid_ring_model.h"
#include "tests/test_support.h"

namespace ringid {
namespace {

using P = Param;
using testing::PaperIdentified;

double WorstRelativeShift(const ModalSolution& a, const ModalSolution& b) {
  double worst = 0;
  for (const Mode& m : a.modes) {
    const Mode* o = b.Find(m.label);
    if (!o) return INFINITY;
    worst = std::max(worst, std::abs(m.eigenvalue - o->eigenvalue) / std::abs(m.eigenvalue));
  }
  return worst;
}

TEST(RollingTest, EveryOscillatoryRootConvergesToTheStandingOneAsSpeedGoesToZero) {
  const RigidRingModel model;
  const Parameters p = PaperIdentified();
  const ModalSolution standing = model.Solve(p);
  ASSERT_TRUE(standing.ok);
  double previous = INFINITY;
  for (double v : {1e-2, 1e-3, 1e-4}) {
    const ModalSolution rolling = model.Solve(p, v);
    ASSERT_TRUE(rolling.ok) << rolling.error;
    ASSERT_EQ(rolling.modes.size(), standing.modes.size());
    const double shift = WorstRelativeShift(standing, rolling);
    // First order in V: ten times slower, ten times closer.
    if (std::isfinite(previous)) {
      EXPECT_GT(previous / shift, 5) << v;
      EXPECT_LT(previous / shift, 20) << v;
    }
    previous = shift;
    // The slip states tend to integrators: their roots go to zero with V.
    ASSERT_FALSE(rolling.real_roots.empty());
    for (double r : rolling.real_roots) EXPECT_LE(std::abs(r), 1e3 * v) << v;
  }
  EXPECT_LT(previous, 1e-4);
}

// Damping and contact removed, the spinning ring is gyroscopic and
// conservative: at any speed every oscillatory root lies on the imaginary
// axis. The seed's printed yaw line (both Omega terms with a + sign) fails this.
TEST(RollingTest, WithoutDampingAndContactTheRotatingRingIsConservative) {
  Parameters p = PaperIdentified();
  for (P c : {P::c_bx, P::c_bz, P::c_btheta, P::c_by, P::c_bgamma, P::c_bpsi}) p[c] = 0;
  p[P::K_cx] = 0;
  p[P::K_cy] = 0;
  p[P::s_h] = 2e-7;
  p[P::m_a] = 15;
  p[P::dm] = 0.3;
  const RigidRingModel model({FindEffect("hub_compliance"), FindEffect("sensor_mass")});
  for (double v : {0.0, 5.0, 20.0, 60.0}) {
    const ModalSolution s = model.Solve(p, v);
    ASSERT_TRUE(s.ok) << s.error;
    // Without contact the in-phase rotation is a rigid spin (a zero root).
    EXPECT_GE(s.modes.size(), 9u) << v;
    for (const Mode& m : s.modes) {
      if (std::abs(m.eigenvalue) < 1e-3) continue;  // the rigid spin, numerically
      EXPECT_LT(std::abs(m.eigenvalue.real()), 1e-9 * std::abs(m.eigenvalue))
          << LabelName(m.label) << " at " << v << " m/s";
    }
  }
}

// A free ring (no contact, no damping) with I_bx = I_bz and equal camber and
// yaw stiffness: Omega I_by couples camber and yaw, I w^2 -+ I_by Omega w - k = 0,
// so the pair splits by +-I_by Omega / (2 I_bx) at low speed.
TEST(RollingTest, AFreeRingSplitsCamberAndYawByTheGyroscopicTerm) {
  Parameters p = PaperIdentified();
  for (P c : {P::c_bx, P::c_bz, P::c_btheta, P::c_by, P::c_bgamma, P::c_bpsi}) p[c] = 0;
  p[P::K_cx] = 0;
  p[P::K_cy] = 0;
  p[P::F_cz0] = 0;
  p[P::I_bz] = p[P::I_bx];
  p[P::k_bpsi] = p[P::k_bgamma];
  const double w0 = std::sqrt(p[P::k_bgamma] / p[P::I_bx]);
  for (double v : {0.05, 0.2}) {
    const double omega = v / p[P::r_e0];
    const double half = p[P::I_by] * omega / (2 * p[P::I_bx]);
    const double mean = std::sqrt(w0 * w0 + half * half);  // w0 to first order
    const ModalSolution s = RigidRingModel().Solve(p, v);
    ASSERT_TRUE(s.ok) << s.error;
    std::vector<double> w;
    for (const Mode& m : s.modes) {
      if (m.plane() == Plane::kOutOfPlane && m.label != ModeLabel::kLateral) {
        w.push_back(m.eigenvalue.imag());
      }
    }
    ASSERT_EQ(w.size(), 2u);
    std::sort(w.begin(), w.end());
    EXPECT_NEAR(w[0], mean - half, 1e-6 * half) << v;
    EXPECT_NEAR(w[1], mean + half, 1e-6 * half) << v;
  }
}

// The reference continuation: tiny steps, each mode paired with the most
// similar shape of the step before; a mode whose pair of roots turned real
// keeps its label until a new oscillating mode takes it back.
std::map<ModeLabel, std::complex<double>> FineContinuation(const RigidRingModel& model,
                                                           const Parameters& p, double speed) {
  ModalSolution prev = model.Solve(p);
  std::vector<ModeLabel> gone;
  const int steps = 3000;
  for (int i = 1; i <= steps; ++i) {
    const MechanicalSystem s = model.Assemble(p, speed * i / steps);
    ModalSolution next = SolveModes(s);
    EXPECT_TRUE(next.ok);
    std::vector<double> best(next.modes.size(), -1);
    for (size_t a = 0; a < next.modes.size(); ++a) {
      Mode& m = next.modes[a];
      for (const Mode& o : prev.modes) {
        const double mac = std::norm(m.shape.dot(o.shape)) /
                           (m.shape.squaredNorm() * o.shape.squaredNorm());
        if (mac > best[a]) best[a] = mac, m.label = o.label;
      }
    }
    if (next.modes.size() > prev.modes.size()) {  // one came back
      EXPECT_EQ(gone.size(), 1u);
      const size_t back = std::min_element(best.begin(), best.end()) - best.begin();
      next.modes[back].label = gone.back();
      gone.pop_back();
    } else if (next.modes.size() < prev.modes.size()) {  // one vanished
      for (const Mode& o : prev.modes) {
        if (!next.Find(o.label)) gone.push_back(o.label);
      }
    }
    prev = next;
  }
  std::map<ModeLabel, std::complex<double>> out;
  for (const Mode& m : prev.modes) out[m.label] = m.eigenvalue;
  return out;
}

// Between 10 and 30 m/s the longitudinal mode passes below the vertical and
// the lateral mode above the yaw mode (paper's parameters).
TEST(RollingTest, LabelsFollowTheStandingOnesThroughCrossingsAndLagsAreNeverPaired) {
  const RigidRingModel model;
  const Parameters p = PaperIdentified();
  const ModalSolution at10 = model.Solve(p, 10), at30 = model.Solve(p, 30);
  ASSERT_TRUE(at10.ok && at30.ok) << at10.error << at30.error;
  auto hz = [](const ModalSolution& s, ModeLabel l) { return s.Find(l)->frequency_hz; };
  EXPECT_LT(hz(at10, ModeLabel::kVertical), hz(at10, ModeLabel::kLongitudinal));
  EXPECT_GT(hz(at30, ModeLabel::kVertical), hz(at30, ModeLabel::kLongitudinal));
  EXPECT_LT(hz(at10, ModeLabel::kLateral), hz(at10, ModeLabel::kYaw));
  EXPECT_GT(hz(at30, ModeLabel::kLateral), hz(at30, ModeLabel::kYaw));
  const auto reference = FineContinuation(model, p, 30);
  ASSERT_EQ(reference.size(), at30.modes.size());
  for (const Mode& m : at30.modes) {
    EXPECT_LT(std::abs(reference.at(m.label) - m.eigenvalue), 1e-9 * std::abs(m.eigenvalue))
        << LabelName(m.label);
  }
  // Seven labelled modes; the slip lag is a real root beside them.
  EXPECT_EQ(at30.modes.size(), 7u);
  EXPECT_FALSE(at30.real_roots.empty());
}

TEST(RollingTest, EveryEffectSolvesAtSpeedAndIsTheBaselineAtSizeZero) {
  Parameters p = PaperIdentified();
  p[P::m_a] = 15;
  const ModalSolution baseline = RigidRingModel().Solve(p, 8);
  ASSERT_TRUE(baseline.ok) << baseline.error;
  for (const Effect* e : EffectCatalogue()) {
    const RigidRingModel model({e});
    const ModalSolution zero = model.Solve(p, 8);
    ASSERT_TRUE(zero.ok) << e->name() << ": " << zero.error;
    EXPECT_LT(WorstRelativeShift(baseline, zero), 1e-12) << e->name();
    Parameters sized = p;
    sized[e->size()] = TypicalScale(e->size()) * (e->size() == P::s_h ? 2 : 1);
    const ModalSolution s = model.Solve(sized, 8);
    ASSERT_TRUE(s.ok) << e->name() << ": " << s.error;
    EXPECT_GE(s.modes.size(), 7u) << e->name();
  }
}

// The model keeps the standstill modes of recent points; what it answers
// from them is bit for bit what a model that never saw the point computes,
// and a copy of the model starts with nothing kept.
TEST(RollingTest, KeptStandstillModesChangeNoResult) {
  const Parameters p = PaperIdentified();
  const RigidRingModel warm;
  for (double v : {0.0, 6.0, 12.0}) warm.Solve(p, v);
  const RigidRingModel copy = warm;
  for (double v : {12.0, 6.0, 0.0, 25.0}) {
    for (const RigidRingModel* m : {&warm, &copy}) {
      const ModalSolution a = m->Solve(p, v), b = RigidRingModel().Solve(p, v);
      ASSERT_TRUE(a.ok && b.ok);
      ASSERT_EQ(a.modes.size(), b.modes.size());
      for (size_t i = 0; i < a.modes.size(); ++i) {
        EXPECT_EQ(a.modes[i].label, b.modes[i].label);
        EXPECT_EQ(a.modes[i].eigenvalue, b.modes[i].eigenvalue) << v;
        EXPECT_EQ(a.modes[i].shape, b.modes[i].shape);
      }
      EXPECT_EQ(a.real_roots, b.real_roots);
    }
  }
}

// Points a fit of a rolling dataset (written as a new user would) visits:
// its initial values at one condition, each scattered log-uniformly within a
// factor 3, as the scattered starts are.
class ScatteredStarts {
 public:
  explicit ScatteredStarts(unsigned seed) : rng_(seed) {
    LoadError e;
    loaded_ = LoadDataset(testing::SourcePath("tests/data/newcomer_rolling.json"),
                          &dataset_, &e);
    EXPECT_TRUE(loaded_) << e.message;
  }
  bool loaded() const { return loaded_; }
  const Dataset& dataset() const { return dataset_; }
  Parameters Next(const RigidRingModel& model, int condition) {
    Parameters p = InitialParameters(dataset_, condition);
    for (Param q : model.parameters()) {
      if (p[q] > 0) p[q] *= std::exp(factor_(rng_));
    }
    return p;
  }
  std::mt19937_64& rng() { return rng_; }

 private:
  Dataset dataset_;
  bool loaded_ = false;
  std::mt19937_64 rng_;
  std::uniform_real_distribution<double> factor_{-std::log(3.0), std::log(3.0)};
};

// Continuation with its predictor and doubling steps, and labels carried
// from anchors, give the labels of the reference continuation in 3000 equal
// steps, on scattered starts of a rolling dataset (factor 3 of its initial
// values), where modes cross, veer and vanish.
TEST(RollingTest, LabelsAtScatteredPointsAreThoseOfTheReferenceContinuation) {
  ScatteredStarts starts(11);
  ASSERT_TRUE(starts.loaded());
  const Dataset& d = starts.dataset();
  const RigidRingModel model;
  int compared = 0;
  for (int n = 0; n < 40; ++n) {
    for (int c = 1; c < static_cast<int>(d.conditions.size()); ++c) {
      const double v = d.conditions[c].speed_m_s;
      const Parameters p = starts.Next(model, c);
      const ModalSolution s = model.Solve(p, v);
      if (!s.ok) continue;
      ++compared;
      const auto reference = FineContinuation(model, p, v);
      for (const Mode& m : s.modes) {
        ASSERT_TRUE(reference.count(m.label)) << LabelName(m.label);
        EXPECT_LT(std::abs(reference.at(m.label) - m.eigenvalue), 1e-9 * std::abs(m.eigenvalue))
            << "point " << n << " at " << v << " m/s: " << LabelName(m.label);
      }
    }
  }
  EXPECT_GE(compared, 60);
}

// A point's labels at speed come from continuation at its anchor, carried by
// one step to the point (docs/rolling.md §5). They are those of continuation
// at the point itself, on scattered starts of a rolling dataset (factor 3 of
// its initial values) and on neighbours at the numeric derivatives' distance.
TEST(RollingTest, LabelsCarriedFromAnAnchorAreThoseOfContinuationAtThePoint) {
  ScatteredStarts starts(7);
  ASSERT_TRUE(starts.loaded());
  const Dataset& d = starts.dataset();
  const RigidRingModel model;
  std::uniform_real_distribution<double> nudge(-1e-3, 1e-3);
  int compared = 0;
  for (int n = 0; n < 1500; ++n) {
    for (int c = 1; c < static_cast<int>(d.conditions.size()); ++c) {
      const double v = d.conditions[c].speed_m_s;
      const Parameters p = starts.Next(model, c);
      Parameters near = p;
      for (Param q : model.parameters()) near[q] *= 1 + nudge(starts.rng());
      for (const Parameters& x : {p, near}) {
        const ModalSolution anchored = model.Solve(x, v);
        const ModalSolution continued = SolveRolling(
            [&](double s) { return model.Assemble(x, s); }, v, SolveModes(model.Assemble(x)));
        ASSERT_EQ(anchored.ok, continued.ok) << anchored.error << continued.error;
        if (!anchored.ok) continue;
        ++compared;
        ASSERT_EQ(anchored.modes.size(), continued.modes.size());
        bool same = true;
        for (size_t i = 0; i < anchored.modes.size(); ++i) {
          EXPECT_EQ(anchored.modes[i].eigenvalue, continued.modes[i].eigenvalue);
          same = same && anchored.modes[i].label == continued.modes[i].label;
        }
        EXPECT_TRUE(same) << "point " << n << " at " << v << " m/s";
        EXPECT_EQ(anchored.vanished, continued.vanished);
      }
    }
  }
  EXPECT_GT(compared, 500);
}

// What a model kept from the points it solved before (standstill modes,
// anchors) changes nothing it answers: points solved forwards, backwards and
// each by a fresh model give the same modes bit for bit.
TEST(RollingTest, RollingModesDoNotDependOnTheOrderOfEvaluation) {
  ScatteredStarts starts(3);
  ASSERT_TRUE(starts.loaded());
  const RigidRingModel model;
  std::uniform_real_distribution<double> nudge(-1e-3, 1e-3);
  std::vector<Parameters> points;
  for (int n = 0; n < 60; ++n) {
    points.push_back(starts.Next(model, 1));
    Parameters near = points.back();
    for (Param q : model.parameters()) near[q] *= 1 + nudge(starts.rng());
    points.push_back(near);
  }
  const double v = starts.dataset().conditions[1].speed_m_s;
  const RigidRingModel forwards, backwards;
  std::vector<ModalSolution> a, b(points.size());
  for (const Parameters& p : points) a.push_back(forwards.Solve(p, v, true));
  for (size_t i = points.size(); i-- > 0;) b[i] = backwards.Solve(points[i], v, true);
  for (size_t i = 0; i < points.size(); ++i) {
    const ModalSolution fresh = RigidRingModel().Solve(points[i], v, true);
    for (const ModalSolution* s : {&a[i], &b[i]}) {
      ASSERT_EQ(s->ok, fresh.ok) << i;
      ASSERT_EQ(s->modes.size(), fresh.modes.size()) << i;
      for (size_t k = 0; k < fresh.modes.size(); ++k) {
        EXPECT_EQ(s->modes[k].label, fresh.modes[k].label) << i;
        EXPECT_EQ(s->modes[k].eigenvalue, fresh.modes[k].eigenvalue) << i;
        EXPECT_EQ(s->modes[k].shape, fresh.modes[k].shape) << i;
        ASSERT_EQ(s->modes[k].derivatives != nullptr, fresh.modes[k].derivatives != nullptr);
        if (fresh.modes[k].derivatives) {
          EXPECT_EQ(s->modes[k].derivatives->eigenvalue, fresh.modes[k].derivatives->eigenvalue);
        }
      }
    }
  }
}

}  // namespace
}  // namespace ringid
