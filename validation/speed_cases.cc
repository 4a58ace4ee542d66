#include "validation/speed_cases.h"

#include <algorithm>
#include <cmath>
#include <random>

#include <Eigen/LU>

#include <Eigen/Eigenvalues>

#include "datasets/synthetic.h"
#include "estimation/identify.h"
#include "model/forced_response.h"
#include "model/modal.h"
#include "model/rigid_ring_model.h"

namespace ringid {

Status SpeedTable1(const std::string& source_dir, bool in_plane_only, Dataset* d) {
  *d = Dataset();
  LoadError e;
  if (!LoadDataset(source_dir + "/datasets/paper/table1.json", d, &e)) {
    return Status::InvalidInput(e.OneLine());
  }
  if (in_plane_only) {
    std::vector<MeasuredMode> keep;
    for (const MeasuredMode& m : d->modes) {
      if (LabelPlane(m.label) == Plane::kInPlane) keep.push_back(m);
    }
    d->modes = keep;
    // Out-of-plane parameters do not move in-plane modes: hold them.
    for (auto it = d->initial.begin(); it != d->initial.end();) {
      if (Info(it->first).group == Group::kOutOfPlane) {
        d->known[it->first] = it->second;
        it = d->initial.erase(it);
      } else {
        ++it;
      }
    }
    for (auto it = d->ties.begin(); it != d->ties.end();) {
      if (Info(it->first).group == Group::kOutOfPlane) it = d->ties.erase(it);
      else ++it;
    }
    d->known[Param::c_bpsi] = d->known[Param::c_bgamma];
    d->known[Param::k_bpsi] = d->known[Param::k_bgamma];
  }
  return Status::Success();
}

Status SpeedPaperParameters(const std::string& source_dir, Parameters* p) {
  LoadError e;
  if (!LoadParameterSet(source_dir + "/datasets/paper/parameters.json", p, &e)) {
    return Status::InvalidInput(e.OneLine());
  }
  return Status::Success();
}

std::vector<SpeedBlock> BareEigenBlocks(const Parameters& p) {
  const MechanicalSystem s = RigidRingModel().Assemble(p);
  std::vector<SpeedBlock> blocks;
  for (const std::vector<Dof>& dofs :
       {std::vector<Dof>{Dof::kXb, Dof::kThetaA, Dof::kThetaB}, std::vector<Dof>{Dof::kZb},
        std::vector<Dof>{Dof::kYb, Dof::kGammaB, Dof::kPsiB}}) {
    const int k = static_cast<int>(dofs.size());
    Eigen::MatrixXd M(k, k), C(k, k), K(k, k);
    for (int a = 0; a < k; ++a) {
      for (int b = 0; b < k; ++b) {
        M(a, b) = s.M()(static_cast<int>(dofs[a]), static_cast<int>(dofs[b]));
        C(a, b) = s.C()(static_cast<int>(dofs[a]), static_cast<int>(dofs[b]));
        K(a, b) = s.K()(static_cast<int>(dofs[a]), static_cast<int>(dofs[b]));
      }
    }
    // Balanced as the model balances it: velocities in units of w.
    double w2 = 0;
    for (int a = 0; a < k; ++a) w2 = std::max(w2, K(a, a) / M(a, a));
    const double w = BalancingFrequency(w2);
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * k, 2 * k);
    A.topRightCorner(k, k).setIdentity() *= w;
    A.bottomLeftCorner(k, k) = -M.inverse() * K / w;
    A.bottomRightCorner(k, k) = -M.inverse() * C;
    blocks.push_back(A);
  }
  return blocks;
}

double BareEigenSolve(const std::vector<SpeedBlock>& blocks, bool vectors) {
  double sink = 0;
  for (const SpeedBlock& A : blocks) {
    Eigen::EigenSolver<SpeedBlock> es(A, vectors);
    if (es.info() != Eigen::Success) return std::nan("");
    sink += vectors ? es.pseudoEigenvectors()(0, 0) : es.eigenvalues()[0].real();
  }
  return sink;
}

void NextSpeedPoint(Parameters* p, int* i) {
  (*p)[Param::k_bx] *= 1 + (++*i % 128 == 0 ? -127e-15 : 1e-15);
}

Status SpeedForcesCase(ForceParameters* parameters, ResponseDataset* data) {
  Dataset d;
  Status s = SpeedCarTire({0, 6, 12}, &d);
  if (!s.ok()) return s;
  IdentifyOptions o;
  o.starts = 1;
  o.residuals.derivatives = Derivatives::kAnalytic;
  IdentifyResult fit;
  Identify(RigidRingModel(), d, o, &fit);
  if (!fit.status.ok()) return fit.status;
  *parameters = ForceParameters::From(fit);
  *data = ResponseDataset{};
  data->name = "speed";
  std::string why;
  const auto forces = [](int k) {
    return std::array<std::complex<double>, kNumLugForces>{300.0 / k, 900.0 / k, 150.0 / k};
  };
  const std::vector<AxleChannel> all = {AxleChannel::kForceX, AxleChannel::kForceZ,
                                        AxleChannel::kForceY, AxleChannel::kMomentX,
                                        AxleChannel::kMomentZ};
  if (!SimulateResponses(RigidRingModel(), ExampleCarTire(), 20, {6, 12, 18}, 5, all, forces, 0.1,
                         nullptr, data, &why)) {
    return Status::Failed(why);
  }
  return Status::Success();
}

Status SpeedCarTire(const std::vector<double>& speeds, Dataset* d) {
  const Parameters truth = ExampleCarTire();
  *d = Dataset();
  d->name = "bench";
  d->format = 2;
  d->conditions.clear();
  for (double v : speeds) {
    Condition c;
    c.name = "v" + std::to_string(static_cast<int>(v));
    c.speed_m_s = v;
    d->conditions.push_back(c);
  }
  std::mt19937_64 rng(7);
  std::string error;
  if (!Simulate(RigidRingModel(), truth, SimulateOptions(), &rng, d, &error)) {
    return Status::InvalidInput(error);
  }
  for (int i = 0; i < kNumParams; ++i) {
    if (IsBaseline(ParamAt(i))) d->known[ParamAt(i)] = truth[ParamAt(i)];
  }
  d->ties = {{Param::c_bz, Param::c_bx}, {Param::k_bz, Param::k_bx},
             {Param::c_bpsi, Param::c_bgamma}, {Param::k_bpsi, Param::k_bgamma}};
  for (const auto& [from, to] : d->ties) d->known.erase(from);
  for (Param p : {Param::c_bx, Param::c_btheta, Param::k_bx, Param::k_btheta, Param::K_cx,
                  Param::sigma_cx, Param::k_cz, Param::c_by, Param::c_bgamma, Param::k_by,
                  Param::k_bgamma, Param::K_cy, Param::sigma_cy, Param::t_0}) {
    d->known.erase(p);
    d->initial[p] = truth[p] * (IsDamping(p) ? 0.8 : 1.25);
  }
  return Status::Success();
}

}  // namespace ringid
