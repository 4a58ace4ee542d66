// The static stiffnesses at the contact (contract §10, model/static_stiffness.h)
// against the .tir's series formulas (docs/tir.md), against a static solve of
// the assembled stiffness matrix written here in another form (the contact in
// series with the structure's compliance, the Sherman–Morrison form), and their
// exact derivatives against Ridders' extrapolated finite differences.
#include "model/static_stiffness.h"

#include <cmath>
#include <string>
#include <vector>

#include <ceres/dynamic_numeric_diff_cost_function.h>
#include <Eigen/LU>
#include <gtest/gtest.h>

#include "datasets/synthetic.h"
#include "model/effects.h"
#include "model/rigid_ring_model.h"
#include "tests/test_support.h"

namespace ringid {
namespace {

using P = Param;
using D = StaticDirection;
using testing::PaperIdentified;
constexpr D kDirections[] = {D::kVertical, D::kLongitudinal, D::kLateral};

double Relative(double a, double b) { return std::abs(a - b) / std::abs(b); }

double Solved(const ModalModel& model, const Parameters& p, D d) {
  const StaticStiffnessResult r = StaticStiffness(model, p, d);
  EXPECT_TRUE(r.ok) << ToString(d) << ": " << r.error;
  return r.value;
}

// VERTICAL_STIFFNESS, LONGITUDINAL_STIFFNESS, LATERAL_STIFFNESS of docs/tir.md.
double Series(const Parameters& p, D d) {
  switch (d) {
    case D::kVertical:
      return 1 / (1 / p[P::k_bz] + 1 / p[P::k_cz]);
    case D::kLongitudinal:
      return 1 / (1 / p[P::k_bx] + p[P::r_e0] * p[P::r_e0] / p[P::k_btheta] +
                  p[P::sigma_cx] / p[P::K_cx]);
    case D::kLateral:
      return 1 / (1 / p[P::k_by] +
                  p[P::r_l0] * p[P::r_l0] / (p[P::k_bgamma] + p[P::r_l0] * p[P::F_cz0]) +
                  p[P::sigma_cy] / p[P::K_cy]);
  }
  return NAN;
}

TEST(StaticStiffnessTest, BaselineIsTheTirSeriesFormulas) {
  for (const Parameters& p : {ExampleCarTire(), PaperIdentified()}) {
    for (D d : kDirections) {
      EXPECT_LT(Relative(Solved(RigidRingModel(), p, d), Series(p, d)), 1e-12) << ToString(d);
    }
  }
}

// The contact element of each direction as docs/model.md §7 lists it
// (elements 9, 11, 17 and the trail entries 20, 21): k f d^T in K.
struct Element {
  double k;
  Eigen::VectorXd f, d;  // over Dof
};
Element ContactOf(const Parameters& p, D direction) {
  Element e{0, Eigen::VectorXd::Zero(kNumDofs), Eigen::VectorXd::Zero(kNumDofs)};
  auto at = [](Eigen::VectorXd& v, Dof dof) -> double& { return v(static_cast<int>(dof)); };
  switch (direction) {
    case D::kVertical:
      e.k = p[P::k_cz];
      at(e.d, Dof::kZb) = 1;
      e.f = e.d;
      break;
    case D::kLongitudinal:
      e.k = p[P::K_cx] / p[P::sigma_cx];
      at(e.d, Dof::kXb) = 1;
      at(e.d, Dof::kThetaB) = -p[P::r_e0];
      e.f = e.d;
      break;
    case D::kLateral:
      e.k = p[P::K_cy] / p[P::sigma_cy];
      at(e.d, Dof::kYb) = 1;
      at(e.d, Dof::kGammaB) = -p[P::r_l0];
      e.f = e.d;
      at(e.f, Dof::kPsiB) = -p[P::t_0];
      break;
  }
  return e;
}

// K = K_s + k f d^T with K_s the structure without the contact: on the held
// axle and the locked rim, the road sees the contact k in series with the
// structure's compliance d^T K_s^-1 f (Sherman–Morrison).
double InSeries(const RigidRingModel& model, const Parameters& p, D direction) {
  const MechanicalSystem s = model.Assemble(p, 0);
  const Element e = ContactOf(p, direction);
  const Eigen::MatrixXd K_s = s.K() - e.k * e.f * e.d.transpose();
  std::vector<int> kept;
  for (int d = 0; d < kNumDofs; ++d) {
    if (s.active(static_cast<Dof>(d)) && static_cast<Dof>(d) != Dof::kThetaA) kept.push_back(d);
  }
  const int n = static_cast<int>(kept.size());
  Eigen::MatrixXd K(n, n);
  Eigen::VectorXd f(n), d(n);
  for (int a = 0; a < n; ++a) {
    f(a) = e.f(kept[a]);
    d(a) = e.d(kept[a]);
    for (int b = 0; b < n; ++b) K(a, b) = K_s(kept[a], kept[b]);
  }
  return 1 / (1 / e.k + d.dot(K.fullPivLu().solve(f)));
}


TEST(StaticStiffnessTest, WithEachEffectIsTheContactInSeriesWithTheAssembledStructure) {
  for (const Parameters& base : {ExampleCarTire(), PaperIdentified()}) {
    for (const Effect* effect : EffectCatalogue()) {
      const RigidRingModel model({effect});
      const Parameters p = testing::WithEffectSized(*effect, base);
      for (D d : kDirections) {
        EXPECT_LT(Relative(Solved(model, p, d), InSeries(model, p, d)), 1e-12)
            << effect->name() << ", " << ToString(d);
      }
    }
  }
}

// What each effect's elements do to the chains of docs/tir.md: the hub's
// spring joins each in series, the anisotropic k_bz + dk_bz carries the
// load, lug coupling stiffens or softens the two planes it joins; the rest
// act on what the static solve holds (theta_a locked), on yaw (which does
// not act back at standstill) or on mass alone.
TEST(StaticStiffnessTest, EachEffectChangesTheSeriesAsItsElementsSay) {
  for (const Parameters& base : {ExampleCarTire(), PaperIdentified()}) {
    for (const Effect* effect : EffectCatalogue()) {
      const RigidRingModel model({effect});
      const Parameters p = testing::WithEffectSized(*effect, base);
      const std::string name = effect->name();
      for (D d : kDirections) {
        const double value = Solved(model, p, d);
        double expected = Series(p, d);
        if (name == "hub_compliance") {
          expected = 1 / (p[P::s_h] + 1 / expected);
        } else if (name == "anisotropic_sidewall" && d == D::kVertical) {
          Parameters stiffer = p;
          stiffer[P::k_bz] += p[P::dk_bz];
          expected = Series(stiffer, d);
        } else if (name == "lug_coupling" && d != D::kVertical) {
          EXPECT_GT(Relative(value, expected), 1e-3) << name << ", " << ToString(d);
          continue;  // its value is the series solve's above
        }
        EXPECT_LT(Relative(value, expected), 1e-12) << name << ", " << ToString(d);
      }
    }
  }
}

// The three stiffnesses as a function of the parameters the model reads,
// each as a multiple u of its value at p: Ceres' Ridders steps are at
// least 1e-2 absolute, so relative coordinates give every parameter steps of
// its own size, and dF/du = p dF/dp.
struct Stiffnesses {
  const ModalModel* model;
  Parameters p;
  std::vector<Param> read;
  bool operator()(double const* const* u, double* out) const {
    Parameters q = p;
    for (size_t i = 0; i < read.size(); ++i) q[read[i]] = p[read[i]] * u[0][i];
    for (D d : kDirections) {
      const StaticStiffnessResult r = StaticStiffness(*model, q, d);
      if (!r.ok) return false;
      out[static_cast<int>(d)] = r.value;
    }
    return true;
  }
};

// The exact derivatives against Ridders' as elasticities (p / F) dF/dp, for
// every parameter the model reads; those it does not read have none.
void ExpectRidders(const RigidRingModel& model, const Parameters& p, const std::string& what) {
  const Stiffnesses functor{&model, p, model.parameters()};
  const int n = static_cast<int>(functor.read.size());
  ceres::NumericDiffOptions options;
  options.ridders_relative_initial_step_size = 1e-3;  // its first step 32 times this
  ceres::DynamicNumericDiffCostFunction<Stiffnesses, ceres::RIDDERS> ridders(
      &functor, ceres::DO_NOT_TAKE_OWNERSHIP, options);
  ridders.AddParameterBlock(n);
  ridders.SetNumResiduals(kNumStaticDirections);
  const Eigen::VectorXd u = Eigen::VectorXd::Ones(n);
  Eigen::Matrix<double, kNumStaticDirections, Eigen::Dynamic, Eigen::RowMajor> J(
      kNumStaticDirections, n);
  Eigen::VectorXd F(kNumStaticDirections);
  const double* parameters[] = {u.data()};
  double* jacobians[] = {J.data()};
  EXPECT_TRUE(ridders.Evaluate(parameters, F.data(), jacobians)) << what;
  for (D d : kDirections) {
    const StaticStiffnessResult r = StaticStiffness(model, p, d, true);
    EXPECT_TRUE(r.ok) << what << ": " << r.error;
    if (!r.ok) continue;
    EXPECT_EQ(r.value, F(static_cast<int>(d))) << what;
    EXPECT_EQ(r.derivative.size(), kNumParams) << what;
    std::vector<bool> read(kNumParams, false);
    for (int i = 0; i < n; ++i) {
      const Param q = functor.read[i];
      read[static_cast<int>(q)] = true;
      const double gap = std::abs(r.derivative(static_cast<int>(q)) * p[q] -
                                  J(static_cast<int>(d), i)) / std::abs(r.value);
      EXPECT_LT(gap, 1e-10) << what << ", " << ToString(d) << ", d/d" << ParamName(q)
                           << ": exact " << r.derivative(static_cast<int>(q)) << ", Ridders "
                           << J(static_cast<int>(d), i) / p[q];
    }
    for (int i = 0; i < kNumParams; ++i) {
      if (!read[i]) EXPECT_EQ(r.derivative(i), 0.0) << what << ", " << ParamName(ParamAt(i));
    }
  }
}

TEST(StaticStiffnessTest, DerivativesMatchRiddersForTheBaselineAndWithEffects) {
  for (const Parameters& p : {ExampleCarTire(), PaperIdentified()}) {
    ExpectRidders(RigidRingModel(), p, "baseline");
    for (const char* name : {"hub_compliance", "lug_coupling", "anisotropic_sidewall"}) {
      const Effect* effect = FindEffect(name);
      ASSERT_NE(effect, nullptr) << name;
      ExpectRidders(RigidRingModel({effect}), testing::WithEffectSized(*effect, p), name);
    }
  }
}

TEST(StaticStiffnessTest, RefusesAnUnsetParameterAndASingularStiffness) {
  Parameters p = ExampleCarTire();
  p[P::k_by] = NAN;
  StaticStiffnessResult r = StaticStiffness(RigidRingModel(), p, D::kVertical, true);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.error, "parameter k_by is not finite");
  p = ExampleCarTire();
  p[P::k_bz] = -p[P::k_cz];  // z_b held by nothing
  r = StaticStiffness(RigidRingModel(), p, D::kLateral);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("static lateral stiffness"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("singular"), std::string::npos) << r.error;
}

}  // namespace
}  // namespace ringid
