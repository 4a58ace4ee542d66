#include "estimation/structure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <Eigen/QR>
#include <Eigen/SVD>

#include "model/structure.h"

namespace ringid::internal {
namespace {

// Singular values below this fraction of the largest are structural zeros:
// exact derivatives leave them at rounding level (about 1e-15).
constexpr double kStructuralRank = 1e-9;

// d parameter / d coordinate i, for every parameter coordinate i sets (its
// own and those tied to it).
Eigen::VectorXd CoordinateColumn(const ParameterSetup& setup, const Parameters& p, int i) {
  Eigen::VectorXd column = Eigen::VectorXd::Zero(kNumParams);
  const Param q = setup.key(i).param;
  const double scale = setup.is_log(i) ? p[q] : TypicalScale(q);
  column[static_cast<int>(q)] = scale;
  for (const auto& [from, to] : setup.ties()) {
    if (to == q) column[static_cast<int>(from)] = scale;
  }
  return column;
}

// An orthonormal basis of the column space of a, at `tolerance`.
Eigen::MatrixXd Orthonormal(const Eigen::MatrixXd& a, double tolerance) {
  if (a.cols() == 0) return a;
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  qr.setThreshold(tolerance);
  const Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(a.rows(), a.rows());
  return q.leftCols(qr.rank());
}

std::string Relation(const ParameterSetup& setup, const Parameters& p, const Eigen::VectorXd& v) {
  std::vector<int> terms;
  for (int i = 0; i < v.size(); ++i) {
    if (std::abs(v[i]) > 1e-8) terms.push_back(i);
  }
  if (terms.size() == 1) return setup.name(terms[0]) + " does not enter the model";
  auto close = [](double a, double b) { return std::abs(a - b) <= 1e-6 * std::max(std::abs(a), std::abs(b)); };
  if (terms.size() == 2) {
    const int a = terms[0], b = terms[1];
    const std::string na = setup.name(a), nb = setup.name(b);
    if (setup.is_log(a) && setup.is_log(b)) {
      if (close(v[a], v[b])) return "only " + na + " / " + nb + " enters the model";
      if (close(v[a], -v[b])) return "only " + na + " * " + nb + " enters the model";
    }
    // Changes of the values themselves.
    const Param qa = setup.key(a).param, qb = setup.key(b).param;
    const double da = v[a] * (setup.is_log(a) ? p[qa] : TypicalScale(qa));
    const double db = v[b] * (setup.is_log(b) ? p[qb] : TypicalScale(qb));
    if (close(da, -db)) return "only " + na + " + " + nb + " enters the model";
    if (close(da, db)) return "only " + na + " - " + nb + " enters the model";
  }
  std::string list;
  char term[96];
  const double big = v.cwiseAbs().maxCoeff();
  for (int i : terms) {
    std::snprintf(term, sizeof term, "%s%s%+.3g %s", list.empty() ? "" : ", ",
                  setup.is_log(i) ? "log " : "", v[i] / big, setup.name(i).c_str());
    list += term;
  }
  return "the model does not change along " + list;
}

}  // namespace

std::string StructuralFreedom::InvarianceOf(int i) const {
  std::string out;
  for (size_t k = 0; k < readable.size(); ++k) {
    if (std::abs(readable[k][i]) > 1e-8) out += (out.empty() ? "" : "; ") + invariances[k];
  }
  return out;
}

StructuralFreedom FindStructuralFreedom(const ModalResiduals& residuals, const Eigen::VectorXd& x) {
  const ParameterSetup& setup = residuals.setup();
  const Dataset& dataset = residuals.dataset();
  const int n = setup.size(), conditions = setup.num_conditions();
  StructuralFreedom out;
  out.directions.resize(n, 0);
  if (n == 0) return out;
  // Rows: each condition's entries; columns: coordinates, then one common
  // factor per condition.
  std::vector<Eigen::RowVectorXd> rows;
  for (int c = 0; c < conditions; ++c) {
    const Parameters p = setup.Decode(x.data(), c);
    const SystemDerivatives d = Differentiate(residuals.model(), p, dataset.conditions[c].speed_m_s);
    Eigen::MatrixXd to_coordinates = Eigen::MatrixXd::Zero(kNumParams, n);
    for (int i = 0; i < n; ++i) {
      if (setup.condition_of(i) < 0 || setup.condition_of(i) == c) {
        to_coordinates.col(i) = CoordinateColumn(setup, p, i);
      }
    }
    const Eigen::MatrixXd scaling = d.scaling * to_coordinates, invariant = d.invariant * to_coordinates;
    for (int r = 0; r < scaling.rows(); ++r) {
      Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(n + conditions);
      row.head(n) = scaling.row(r);
      row[n + c] = d.scaling_value[r];
      rows.push_back(row);
    }
    for (int r = 0; r < invariant.rows(); ++r) {
      Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(n + conditions);
      row.head(n) = invariant.row(r);
      rows.push_back(row);
    }
  }
  // A prior decides the direction it has a component in.
  for (const auto& prior : residuals.priors()) {
    Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(n + conditions);
    row[prior.coordinate] = 1;
    rows.push_back(row);
  }
  Eigen::MatrixXd g(rows.size(), n + conditions);
  int kept = 0;
  for (const Eigen::RowVectorXd& row : rows) {
    // Derivatives that overflow at an extreme point decide nothing: no claim.
    if (!row.allFinite()) return out;
    const double norm = row.norm();
    if (norm > 0) g.row(kept++) = row / norm;
  }
  g.conservativeResize(kept, Eigen::NoChange);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(g, Eigen::ComputeFullV);
  const Eigen::VectorXd& sv = svd.singularValues();
  const double smax = sv.size() ? sv[0] : 0;
  int rank = 0;
  for (int k = 0; k < sv.size(); ++k) rank += sv[k] > kStructuralRank * smax;
  const Eigen::MatrixXd null = svd.matrixV().rightCols(n + conditions - rank);
  out.directions = Orthonormal(null.topRows(n), 1e-8);
  if (out.directions.cols() == 0) return out;
  // A readable basis: reduced row echelon form of the directions, pivoting on
  // the largest entry.
  Eigen::MatrixXd e = out.directions.transpose();
  for (int r = 0; r < e.rows(); ++r) {
    Eigen::Index row, col;
    e.bottomRows(e.rows() - r).cwiseAbs().maxCoeff(&row, &col);
    e.row(r).swap(e.row(r + row));
    e.row(r) /= e(r, col);
    for (int o = 0; o < e.rows(); ++o) {
      if (o != r) e.row(o) -= e(o, col) * e.row(r);
    }
  }
  const Parameters p = setup.Decode(x.data(), 0);  // values, for sums and differences
  for (int r = 0; r < e.rows(); ++r) {
    Eigen::VectorXd v = e.row(r).transpose();
    for (int i = 0; i < n; ++i) {
      if (std::abs(v[i]) < 1e-10) v[i] = 0;
    }
    out.readable.push_back(v);
    out.invariances.push_back(Relation(setup, p, v));
  }
  return out;
}

}  // namespace ringid::internal
