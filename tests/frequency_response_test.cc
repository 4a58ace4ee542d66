// The model's frequency response functions (model/frequency_response.h,
// contract §9) against a second-order system written here from
// docs/model.md's eqs. (12) and (15) (the contact springs K/sigma), with
// contract §9's point combinations written out by hand, and their exact
// derivatives against Ridders' extrapolated differences, standing and
// rolling, with effects. Rolling against a time integration:
// forced_response_test.cc (the axle channels go through the same solve).
#include "model/frequency_response.h"

#include <cmath>
#include <cstdio>
#include <complex>
#include <string>
#include <vector>

#include <ceres/dynamic_numeric_diff_cost_function.h>
#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "datasets/synthetic.h"
#include "model/rigid_ring_model.h"
#include "tests/test_support.h"

namespace ringid {
namespace {

using P = Param;
using cd = std::complex<double>;

// Eqs. (12) and (15) of docs/model.md over q = [x_b, z_b, theta_a, theta_b,
// y_b, gamma_b, psi_b], the hub held.
struct SecondOrder {
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(7, 7), C = M, K = M;
  explicit SecondOrder(const Parameters& p) {
    M.diagonal() << p[P::m_b], p[P::m_b], p[P::I_ay], p[P::I_by], p[P::m_b], p[P::I_bx],
        p[P::I_bz];
    const double kx = p[P::K_cx] / p[P::sigma_cx], ky = p[P::K_cy] / p[P::sigma_cy];
    const double r = p[P::r_e0], rl = p[P::r_l0], t = p[P::t_0];
    // In-plane: sidewall x, z, the rotational sidewall between rim and belt,
    // the contact's k_cz, and the slip spring on x_b - r_e0 theta_b.
    K(0, 0) = p[P::k_bx] + kx;
    K(0, 3) = K(3, 0) = -r * kx;
    K(3, 3) = p[P::k_btheta] + r * r * kx;
    K(2, 2) = p[P::k_btheta];
    K(2, 3) = K(3, 2) = -p[P::k_btheta];
    K(1, 1) = p[P::k_bz] + p[P::k_cz];
    C(0, 0) = p[P::c_bx];
    C(1, 1) = p[P::c_bz];
    C(2, 2) = C(3, 3) = p[P::c_btheta];
    C(2, 3) = C(3, 2) = -p[P::c_btheta];
    // Out-of-plane, S of eq. (15) as corrected.
    K(4, 4) = p[P::k_by] + ky;
    K(4, 5) = K(5, 4) = -rl * ky;
    K(5, 5) = p[P::k_bgamma] + rl * rl * ky + rl * p[P::F_cz0];
    K(6, 4) = -t * ky;
    K(6, 5) = rl * t * ky;
    K(6, 6) = p[P::k_bpsi];
    C(4, 4) = p[P::c_by];
    C(5, 5) = p[P::c_bgamma];
    C(6, 6) = p[P::c_bpsi];
  }
  // g^T (K - w^2 M + i w C)^-1 b (i w)^order.
  cd H(const Eigen::VectorXd& g, const Eigen::VectorXd& b, double hz, int order) const {
    const double w = 2 * M_PI * hz;
    const Eigen::MatrixXcd D = (K - w * w * M).cast<cd>() + cd(0, w) * C.cast<cd>();
    return std::pow(cd(0, w), order) * g.cast<cd>().dot(D.partialPivLu().solve(b.cast<cd>()));
  }
};

// A point on the belt, contract §9: x_b: d_x, z_b: d_z, theta_b: d_z p_x -
// d_x p_z, y_b: d_y, gamma_b: d_z p_y - d_y p_z, psi_b: d_y p_x - d_x p_y;
// on the rim theta_a: d_z p_x - d_x p_z alone.
struct Point {
  bool rim;
  double p[3], d[3];
  Eigen::VectorXd Vector() const {
    Eigen::VectorXd v = Eigen::VectorXd::Zero(7);
    const double theta = d[2] * p[0] - d[0] * p[2];
    if (rim) {
      v(2) = theta;
      return v;
    }
    v << d[0], d[2], 0, theta, d[1], d[2] * p[1] - d[1] * p[2], d[1] * p[0] - d[0] * p[1];
    return v;
  }
  Coordinates Combination() const {
    const Dof order[] = {Dof::kXb, Dof::kZb, Dof::kThetaA, Dof::kThetaB,
                         Dof::kYb, Dof::kGammaB, Dof::kPsiB};
    const Eigen::VectorXd v = Vector();
    Coordinates c;
    for (int i = 0; i < 7; ++i) {
      if (v(i) != 0) c.push_back({order[i], v(i)});
    }
    return c;
  }
};

// A hammer test: blows at the top of the tread (tangential), on its side
// (lateral, oblique) and radially at the front; accelerometers on the tread
// and the rim, one velocity and one displacement pickup.
const Point kBlows[] = {{false, {0, 0, -0.31}, {1, 0, 0}},
                        {false, {0, 0.08, -0.31}, {0, 1, 0}},
                        {false, {0.31, 0, 0}, {-1, 0, 0}},
                        {false, {0.2, 0.05, -0.2}, {0.3, 0.8, -0.5}}};
const Point kPickups[] = {{false, {0, 0, -0.31}, {0, 0, 1}},   {false, {0.31, 0, 0}, {1, 0, 0}},
                          {false, {0, 0.1, -0.3}, {0, 1, 0}},  {true, {0, 0, -0.2}, {1, 0, 0}},
                          {false, {-0.2, -0.1, 0.2}, {0.6, 0.6, 0.5}}};
const int kOrders[] = {2, 2, 1, 2, 0};

ResponseRequest HammerTest(const std::vector<double>& hz) {
  ResponseRequest r;
  r.frequencies_hz = hz;
  for (const Point& b : kBlows) r.inputs.push_back({std::nullopt, b.Combination()});
  for (int o = 0; o < 5; ++o) {
    r.outputs.push_back({std::nullopt, kPickups[o].Combination(), kOrders[o]});
    for (int i = 0; i < 4; ++i) r.pairs.push_back({o, i});
  }
  return r;
}

TEST(FrequencyResponseTest, StandingItIsTheSecondOrderSystemOfEqs12And15) {
  for (const Parameters& p : {ExampleCarTire(), testing::PaperIdentified()}) {
    const SecondOrder truth(p);
    const std::vector<double> hz = {1, 20, 45, 60, 80, 95, 110, 150, 300};
    const ResponseResult r = FrequencyResponse(RigidRingModel(), p, 0, HammerTest(hz));
    ASSERT_TRUE(r.ok) << r.error;
    for (size_t l = 0; l < hz.size(); ++l) {
      for (int f = 0; f < 20; ++f) {
        const int o = f / 4, i = f % 4;
        const cd expected =
            truth.H(kPickups[o].Vector(), kBlows[i].Vector(), hz[l], kOrders[o]);
        EXPECT_LE(std::abs(r.H(l, f) - expected), 1e-10 * std::abs(expected))
            << hz[l] << " Hz, pickup " << o << ", blow " << i << ": " << r.H(l, f) << " vs "
            << expected;
      }
    }
  }
}

// Every entry's real and imaginary part, as functions of relative
// multipliers u of the parameters the model reads (Ridders' steps are
// absolute, so each parameter gets steps of its own size; dH/du = p dH/dp).
struct Entries {
  const ModalModel* model;
  Parameters p;
  std::vector<Param> read;
  double speed;
  ResponseRequest request;
  bool operator()(double const* const* u, double* out) const {
    Parameters q = p;
    for (size_t i = 0; i < read.size(); ++i) q[read[i]] = p[read[i]] * u[0][i];
    const ResponseResult r = FrequencyResponse(*model, q, speed, request);
    if (!r.ok) return false;
    for (int k = 0; k < r.H.size(); ++k) {
      out[2 * k] = r.H(k % r.H.rows(), k / r.H.rows()).real();
      out[2 * k + 1] = r.H(k % r.H.rows(), k / r.H.rows()).imag();
    }
    return true;
  }
};

void ExpectRidders(const RigidRingModel& model, const Parameters& p, double speed,
                   const ResponseRequest& request, const std::string& what) {
  const Entries functor{&model, p, model.parameters(), speed, request};
  const int n = static_cast<int>(functor.read.size());
  const int lines = static_cast<int>(request.frequencies_hz.size());
  const int entries = lines * static_cast<int>(request.pairs.size());
  ceres::NumericDiffOptions options;
  options.ridders_relative_initial_step_size = 1e-3;
  ceres::DynamicNumericDiffCostFunction<Entries, ceres::RIDDERS> ridders(
      &functor, ceres::DO_NOT_TAKE_OWNERSHIP, options);
  ridders.AddParameterBlock(n);
  ridders.SetNumResiduals(2 * entries);
  const Eigen::VectorXd u = Eigen::VectorXd::Ones(n);
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> J(2 * entries, n);
  Eigen::VectorXd values(2 * entries);
  const double* parameters[] = {u.data()};
  double* jacobians[] = {J.data()};
  ASSERT_TRUE(ridders.Evaluate(parameters, values.data(), jacobians)) << what;
  std::vector<int> params;
  for (Param q : functor.read) params.push_back(static_cast<int>(q));
  const ResponseResult r = FrequencyResponse(model, p, speed, request, &params);
  ASSERT_TRUE(r.ok) << what << ": " << r.error;
  ASSERT_EQ(r.dH.cols(), static_cast<Eigen::Index>(params.size()));
  double worst = 0;
  for (int k = 0; k < n; ++k) {
    for (int e = 0; e < entries; ++e) {
      const int l = e % lines, f = e / lines;
      const cd exact = r.dH(e, k) * p[functor.read[k]];  // e = f * lines + l
      const cd numeric(J(2 * e, k), J(2 * e + 1, k));
      // Relative to the largest entry of the line's function: the elasticity
      // of a near-zero entry is what it is compared with.
      // A function zero at p (across the planes) against the largest of all.
      double scale = 0;
      for (int m = 0; m < lines; ++m) scale = std::max(scale, std::abs(r.H(m, f)));
      if (scale == 0) scale = r.H.cwiseAbs().maxCoeff();
      const double gap = std::abs(exact - numeric) / scale;
      worst = std::max(worst, gap);
      EXPECT_LT(gap, 1e-9) << what << ", d/d" << ParamName(functor.read[k]) << ", line "
                           << request.frequencies_hz[l] << " Hz, function " << f << ": exact "
                           << exact << ", Ridders " << numeric;
    }
  }
  char gap[32];
  std::snprintf(gap, sizeof gap, "%.2g", worst);
  ::testing::Test::RecordProperty(what + ": worst gap", gap);
}

TEST(FrequencyResponseTest, DerivativesMatchRiddersStandingAndRollingWithEffects) {
  const std::vector<double> hz = {12, 47, 83, 140};
  // Standing: the hammer test; rolling: the contact forces in, the axle
  // channels and two coordinates out (contract §9 at speed).
  ResponseRequest rolling;
  rolling.frequencies_hz = hz;
  for (LugForce f : {LugForce::kFx, LugForce::kFz, LugForce::kFy}) rolling.inputs.push_back({f, {}});
  for (int c = 0; c < kNumAxleChannels; ++c) {
    rolling.outputs.push_back({static_cast<AxleChannel>(c), {}, 0});
  }
  rolling.outputs.push_back({std::nullopt, {{Dof::kXb, 1}, {Dof::kThetaB, 0.3}}, 2});
  rolling.outputs.push_back({std::nullopt, {{Dof::kYb, 1}, {Dof::kPsiB, -0.1}}, 1});
  for (int o = 0; o < 7; ++o) {
    for (int i = 0; i < 3; ++i) rolling.pairs.push_back({o, i});
  }
  const Parameters car = ExampleCarTire();
  ExpectRidders(RigidRingModel(), car, 0, HammerTest(hz), "standing");
  ExpectRidders(RigidRingModel(), car, 12, rolling, "rolling");
  for (const char* name : {"hub_compliance", "lug_coupling", "anisotropic_sidewall",
                           "sensor_mass", "contact_yaw_stiffness"}) {
    const Effect* effect = FindEffect(name);
    ASSERT_NE(effect, nullptr) << name;
    const RigidRingModel model({effect});
    const Parameters p = testing::WithEffectSized(*effect, car);
    ExpectRidders(model, p, 0, HammerTest(hz), std::string(name) + ", standing");
    ExpectRidders(model, p, 12, rolling, std::string(name) + ", rolling");
  }
}

TEST(FrequencyResponseTest, ACoordinateTheModelLacksIsRefused) {
  ResponseRequest r;
  r.frequencies_hz = {10};
  r.inputs.push_back({std::nullopt, {{Dof::kXa, 1}}});
  r.outputs.push_back({std::nullopt, {{Dof::kXb, 1}}, 0});
  r.pairs.push_back({0, 0});
  const ResponseResult without = FrequencyResponse(RigidRingModel(), ExampleCarTire(), 0, r);
  EXPECT_FALSE(without.ok);
  EXPECT_EQ(without.error, "an input acts on x_a, which the model lacks");
  EXPECT_EQ(MissingCoordinate(RigidRingModel(), r.inputs[0].coordinates), Dof::kXa);
  const Effect* hub = FindEffect("hub_compliance");
  const ResponseResult with = FrequencyResponse(RigidRingModel({hub}),
                                                testing::WithEffectSized(*hub, ExampleCarTire()), 0, r);
  EXPECT_TRUE(with.ok) << with.error;
  EXPECT_FALSE(MissingCoordinate(RigidRingModel({hub}), r.inputs[0].coordinates));
}

}  // namespace
}  // namespace ringid
