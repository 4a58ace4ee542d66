#include "tests/test_support.h"

#include <gtest/gtest.h>

#include "apps/reports.h"

namespace ringid::testing {

std::string SourcePath(const std::string& relative) {
  return std::string(RINGID_SOURCE_DIR) + "/" + relative;
}

Parameters Table2() {
  Parameters p;
  using P = Param;
  p[P::c_bx] = p[P::c_bz] = 1.38e3;
  p[P::c_btheta] = 1.85e1;
  p[P::k_bx] = p[P::k_bz] = 3.84e5;
  p[P::k_btheta] = 7.67e3;
  p[P::K_cx] = 1.03e4;
  p[P::sigma_cx] = 6.73e-2;
  p[P::r_e0] = 3.19e-1;
  p[P::k_cz] = 3.04e5;
  p[P::c_by] = 1.21e3;
  p[P::c_bgamma] = p[P::c_bpsi] = 6.06;
  p[P::k_by] = 2.81e5;
  p[P::k_bgamma] = p[P::k_bpsi] = 1.41e3;
  p[P::K_cy] = 6.37e2;
  p[P::sigma_cy] = 1.17e-3;
  p[P::r_l0] = 2.58e-3;
  p[P::t_0] = 1.35e-3;
  return p;
}

Parameters PaperIdentified() {
  Parameters shipped;
  LoadError error;
  EXPECT_TRUE(LoadParameterSet(SourcePath("datasets/paper/parameters.json"),
                               &shipped, &error))
      << error.OneLine();
  Parameters p = Table2();
  for (Param q : {Param::m_b, Param::I_ay, Param::I_by, Param::I_bx,
                  Param::I_bz, Param::F_cz0}) {
    p[q] = shipped[q];
  }
  return p;
}

Dataset SyntheticDataset(const RigidRingModel& model, const Parameters& truth,
                         double freq_rel_sigma, double damping_sigma,
                         double shape_sigma, std::mt19937_64* rng) {
  std::normal_distribution<double> n(0, 1);
  const ModalSolution s = model.Solve(truth);
  EXPECT_TRUE(s.ok) << s.error;
  Dataset d;
  d.name = "synthetic";
  d.path = "synthetic";
  for (const Mode& m : s.modes) {
    MeasuredMode mm;
    mm.label = m.label;
    mm.frequency_hz = m.frequency_hz * (1 + freq_rel_sigma * n(*rng));
    mm.frequency_sigma_hz = freq_rel_sigma * m.frequency_hz;
    mm.damping_ratio = m.damping_ratio + damping_sigma * n(*rng);
    mm.damping_sigma = damping_sigma;
    const RealShapeVector u = m.RealShape();
    for (int i = 0; i < kNumDofs; ++i) {
      const Dof dof = static_cast<Dof>(i);
      if (DofPlane(dof) == m.plane()) {
        mm.shape.emplace_back(dof, u[i] + shape_sigma * n(*rng));
      }
    }
    mm.shape_sigma = shape_sigma;
    d.modes.push_back(mm);
  }
  return d;
}

}  // namespace ringid::testing
