#include "estimation/score.h"

#include <cmath>
#include <string>
#include <vector>

#include <Eigen/SVD>

#include "estimation/problem.h"
#include "estimation/statistics.h"
#include "model/effects.h"

namespace ringid {
namespace internal {
namespace {

// A signature column counts as absorbed where its part outside the baseline's
// span is this small against itself: a structural invariance (a sensor mass
// against free m_b, I_by, I_bx, I_bz) leaves rounding only.
constexpr double kAbsorbedPart = 1e-6;

// Orthonormal columns spanning the columns of A above `tolerance` of its
// largest singular value.
Eigen::MatrixXd Span(const Eigen::MatrixXd& A, double tolerance) {
  if (A.cols() == 0) return Eigen::MatrixXd(A.rows(), 0);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeThinU);
  const Eigen::VectorXd& s = svd.singularValues();
  int rank = 0;
  while (rank < s.size() && s[rank] > tolerance * s[0]) ++rank;
  return svd.matrixU().leftCols(rank);
}

}  // namespace

Dataset EffectAtZero(const Effect& effect, const Dataset& warm) {
  Dataset at = warm;
  for (Param p : effect.parameters()) {
    if (!at.known.count(p)) at.initial[p] = Info(p).domain == Domain::kPositive ? TypicalScale(p) : 0;
  }
  return at;
}

EffectScore ScoreEffect(const RigidRingModel& baseline, const Effect& effect, const Dataset& warm,
                        const ResidualOptions& residuals, double rank_tolerance) {
  EffectScore out;
  Status status;
  const auto problem =
      Problem::Create(baseline.With(&effect), EffectAtZero(effect, warm), residuals, &status);
  if (!problem) return out;
  const Eigen::VectorXd x0 = problem->start();
  Eigen::VectorXd r0;
  Eigen::MatrixXd J;
  if (!problem->Evaluate(x0, &r0, &J)) return out;

  // The baseline's columns (every coordinate but the effect's), and the
  // sizing parameters'.
  std::vector<int> base, size;
  for (int i = 0; i < problem->num_coordinates(); ++i) {
    const std::string name = problem->coordinate_name(i);
    bool mine = false, sizes = false;
    for (Param p : effect.parameters()) {
      if (name == ParamName(p)) mine = true, sizes = Info(p).domain != Domain::kPositive;
    }
    if (!mine) base.push_back(i);
    if (sizes) size.push_back(i);
  }
  Eigen::MatrixXd B(J.rows(), base.size()), S(J.rows(), size.size());
  for (size_t j = 0; j < base.size(); ++j) B.col(j) = J.col(base[j]);
  for (size_t j = 0; j < size.size(); ++j) {
    S.col(j) = J.col(size[j]);
    if (S.col(j).norm() > 0) continue;
    out.smooth = false;
    const double h = kScoreStep;  // the coordinate is the value in typical scales
    Eigen::VectorXd x = x0, r;
    x[size[j]] += h;
    if (!problem->Evaluate(x, &r)) return out;  // a mode lost: no first order to read
    S.col(j) = (r - r0) / h;
  }
  const Eigen::MatrixXd U = Span(B, rank_tolerance);
  Eigen::MatrixXd outside = S - U * (U.transpose() * S);
  std::vector<int> seen;
  for (int j = 0; j < S.cols(); ++j) {
    if (outside.col(j).norm() > kAbsorbedPart * S.col(j).norm()) seen.push_back(j);
  }
  Eigen::MatrixXd kept(S.rows(), seen.size());  // each column scaled to 1 for the rank
  for (size_t j = 0; j < seen.size(); ++j) kept.col(j) = outside.col(seen[j]).normalized();
  out.signature = Span(kept, rank_tolerance);
  out.dof = static_cast<int>(out.signature.cols());
  out.ok = true;
  if (out.dof == 0) return out;  // absorbed whole: nothing to test
  const Eigen::VectorXd pull = out.signature.transpose() * r0;
  out.statistic = pull.squaredNorm();
  const Param only = *ParseParam(problem->coordinate_name(size[seen[0]]));
  if (out.dof == 1 && seen.size() == 1 && Info(only).domain == Domain::kNonNegative) {
    // One-sided: a size above 0 lowers the cost where d cost / d size < 0.
    const double z = -kept.col(0).dot(r0) / kept.col(0).norm();
    out.statistic = z > 0 ? z * z : 0.0;
    out.p = 0.5 * std::erfc(z / std::sqrt(2.0));
  } else {
    out.p = ChiSquareTail(out.statistic, out.dof);
  }
  return out;
}

double SignatureOverlap(const EffectScore& a, const EffectScore& b) {
  if (a.signature.cols() == 0 || b.signature.cols() == 0 ||
      a.signature.rows() != b.signature.rows()) {
    return 0;
  }
  const Eigen::MatrixXd c = a.signature.transpose() * b.signature;
  return Eigen::JacobiSVD<Eigen::MatrixXd>(c).singularValues()[0];
}

}  // namespace internal
}  // namespace ringid
