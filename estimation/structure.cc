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

// The rows of the structural test: each condition's entries and lag poles,
// then the priors, by columns: the free coordinates, then `extra` parameters
// as if free (log for positive ones, the parameters tied to one following
// it), then one common factor per condition. Not normalised, not checked.
void StructuralRows(const ModalResiduals& residuals, const Eigen::VectorXd& x,
                    const std::vector<Param>& extra, Eigen::MatrixXd* g) {
  const ParameterSetup& setup = residuals.setup();
  const Dataset& dataset = residuals.dataset();
  const int n = setup.size(), k = static_cast<int>(extra.size());
  const int conditions = setup.num_conditions(), cols = n + k + conditions;
  std::vector<Eigen::RowVectorXd> rows;
  for (int c = 0; c < conditions; ++c) {
    const Parameters p = setup.Decode(x.data(), c);
    const SystemDerivatives d = Differentiate(residuals.model(), p, dataset.conditions[c].speed_m_s);
    Eigen::MatrixXd to_columns = Eigen::MatrixXd::Zero(kNumParams, n + k);
    for (int i = 0; i < n; ++i) {
      if (setup.condition_of(i) < 0 || setup.condition_of(i) == c) {
        to_columns.col(i) = CoordinateColumn(setup, p, i);
      }
    }
    for (int j = 0; j < k; ++j) {
      const Param q = extra[j];
      const double scale = Info(q).domain == Domain::kPositive ? p[q] : TypicalScale(q);
      to_columns(static_cast<int>(q), n + j) = scale;
      for (const auto& [from, to] : setup.ties()) {
        if (to == q) to_columns(static_cast<int>(from), n + j) = scale;
      }
    }
    const Eigen::MatrixXd scaling = d.scaling * to_columns, invariant = d.invariant * to_columns;
    for (int r = 0; r < scaling.rows(); ++r) {
      Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(cols);
      row.head(n + k) = scaling.row(r);
      row[n + k + c] = d.scaling_value[r];
      rows.push_back(row);
    }
    for (int r = 0; r < invariant.rows(); ++r) {
      Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(cols);
      row.head(n + k) = invariant.row(r);
      rows.push_back(row);
    }
    // A measurement that sees the system's scale (a static stiffness) leaves
    // the condition no common factor.
    bool scale_seen = false;
    for (int i = residuals.row_begin(c); i < residuals.row_begin(c + 1); ++i) {
      const Measurement* m = residuals.slots()[i].measurement;
      scale_seen = scale_seen || (m && m->SeesScale());
    }
    if (scale_seen) {
      Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(cols);
      row[n + k + c] = 1;
      rows.push_back(row);
    }
  }
  // A prior decides the direction it has a component in.
  for (const auto& prior : residuals.priors()) {
    Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(cols);
    row[prior.coordinate] = 1;
    rows.push_back(row);
  }
  g->resize(rows.size(), cols);
  for (size_t r = 0; r < rows.size(); ++r) g->row(r) = rows[r];
}

// Columns 0..n-1 (the free coordinates), then the common factors of g (its
// last `conditions`).
std::vector<int> FreeColumns(int n, int conditions, int total) {
  std::vector<int> keep;
  for (int i = 0; i < n; ++i) keep.push_back(i);
  for (int c = 0; c < conditions; ++c) keep.push_back(total - conditions + c);
  return keep;
}

}  // namespace

std::string MeasuredCombination(const ParameterSetup& setup, const Parameters& p, int i, Param q,
                                double vi, double vq, double tolerance) {
  const std::string ni = setup.name(i), nq = ParamName(q);
  auto close = [&](double a, double b) { return std::abs(a - b) <= tolerance * std::max(std::abs(a), std::abs(b)); };
  const bool log_q = Info(q).domain == Domain::kPositive;
  if (setup.is_log(i) && log_q) {
    if (close(vi, vq)) return ni + "/" + nq;
    if (close(vi, -vq)) return ni + "*" + nq;
  }
  // Changes of the values themselves: d i / d q along the direction.
  const Param qi = setup.key(i).param;
  const double di = vi * (setup.is_log(i) ? p[qi] : TypicalScale(qi));
  const double dq = vq * (log_q ? p[q] : TypicalScale(q));
  if (close(di, -dq)) return ni + " + " + nq;
  if (close(di, dq)) return ni + " - " + nq;
  char text[160];
  if (setup.is_log(i) && log_q) {  // i / q^r stays, r = vi / vq
    const double r = vi / vq;
    std::snprintf(text, sizeof text, "%s%s%s^%.2g", ni.c_str(), r > 0 ? "/" : "*", nq.c_str(),
                  std::abs(r));
    return text;
  }
  std::snprintf(text, sizeof text, "%s %s %.4g %s (to first order)", ni.c_str(),
                di / dq < 0 ? "+" : "-", std::abs(di / dq), nq.c_str());
  return text;
}

std::string StructuralFreedom::InvarianceOf(int i) const {
  std::string out;
  for (size_t k = 0; k < readable.size(); ++k) {
    if (std::abs(readable[k][i]) > 1e-8) out += (out.empty() ? "" : "; ") + invariances[k];
  }
  return out;
}

namespace {

// For every known parameter, as if freed: one decomposition serves them all.
// `outside`: entering rows b does not, so never in b's range.
// q gains a free direction exactly when its column a lies in the range of
// b, w = b^+ a, b w = a; the direction is (-w, 1) (w is orthogonal to b's
// own null space), and freeing q adds the singular value
// |b w - a| / sqrt(1 + |w|^2), structural below kStructuralRank.
std::vector<KnownDependence> KnownDependenceOf(const ParameterSetup& setup, const Parameters& p,
                                               const std::vector<Param>& known,
                                               const std::vector<bool>& outside,
                                               const Eigen::MatrixXd& b, const Eigen::MatrixXd& a,
                                               const Eigen::JacobiSVD<Eigen::MatrixXd>& svd,
                                               int rank) {
  std::vector<KnownDependence> out;
  const int n = setup.size();
  const Eigen::VectorXd sv = svd.singularValues().head(rank);
  const double smax = rank ? sv[0] : 0;
  const Eigen::MatrixXd along = svd.matrixU().leftCols(rank).transpose() * a;
  for (size_t j = 0; j < known.size(); ++j) {
    if (outside[j] || !a.col(j).allFinite() || a.col(j).squaredNorm() == 0) continue;
    const Eigen::VectorXd w = svd.matrixV().leftCols(rank) * along.col(j).cwiseQuotient(sv);
    const double gained = (b * w - a.col(j)).norm() / std::sqrt(1 + w.squaredNorm());
    if (!(gained <= kStructuralRank * std::max(smax, a.col(j).norm()))) continue;
    const double vq = 1 / (1 + w.squaredNorm());  // q's part of (-w, 1), normalised
    if (!(vq > 1e-6)) continue;  // freeing q adds no direction worth naming
    for (int i = 0; i < n; ++i) {
      if (std::abs(w[i]) <= 1e-6) continue;
      KnownDependence d;
      d.coordinate = i;
      d.known = known[j];
      d.known_value = p[known[j]];
      d.measured = MeasuredCombination(setup, p, i, known[j], -w[i] * vq, vq, 1e-6);
      out.push_back(d);
    }
  }
  return out;
}

}  // namespace

StructuralFreedom FindStructuralFreedom(const ModalResiduals& residuals, const Eigen::VectorXd& x) {
  const ParameterSetup& setup = residuals.setup();
  const int n = setup.size(), conditions = setup.num_conditions();
  StructuralFreedom out;
  out.directions.resize(n, 0);
  if (n == 0) return out;
  std::vector<Param> known;  // as if free, for known_dependence
  for (Param q : residuals.model().parameters()) {
    bool fixed = !setup.ties().count(q);
    for (int c = 0; c < conditions; ++c) fixed = fixed && setup.CoordinateOf(q, c) < 0;
    if (fixed) known.push_back(q);
  }
  const int k = static_cast<int>(known.size());
  Eigen::MatrixXd g;
  StructuralRows(residuals, x, known, &g);
  // b: the free coordinates and common factors, rows normalised (a known
  // column keeps its row's scale). A known parameter that enters a row b
  // does not is out of b's range there: no free direction moves it.
  const std::vector<int> keep = FreeColumns(n, conditions, n + k + conditions);
  Eigen::MatrixXd b(g.rows(), keep.size()), a(g.rows(), k);
  std::vector<bool> outside(k, false);
  for (int r = 0; r < g.rows(); ++r) {  // a by element: it may have no column
    for (size_t j = 0; j < keep.size(); ++j) b(r, j) = g(r, keep[j]);
    const double b_norm = b.row(r).norm();
    for (int j = 0; j < k; ++j) {
      if (b_norm > 0) {
        a(r, j) = g(r, n + j) / b_norm;
      } else {
        outside[j] = outside[j] || g(r, n + j) != 0;
        a(r, j) = 0;
      }
    }
    if (b_norm > 0) b.row(r) /= b_norm;
  }
  if (!b.allFinite()) return out;  // an extreme point decides nothing
  const int cols = static_cast<int>(keep.size());
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(b, Eigen::ComputeThinU | Eigen::ComputeFullV);
  const Eigen::VectorXd& sv = svd.singularValues();
  const double smax = sv.size() ? sv[0] : 0;
  int rank = 0;
  for (int j = 0; j < sv.size(); ++j) rank += sv[j] > kStructuralRank * smax;
  const Parameters p = setup.Decode(x.data(), 0);  // values, for sums and differences
  if (k > 0) out.known_dependence = KnownDependenceOf(setup, p, known, outside, b, a, svd, rank);
  out.directions = Orthonormal(svd.matrixV().rightCols(cols - rank).topRows(n), 1e-8);
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
  // In the order of their first coordinates (not of the SVD's basis).
  std::vector<std::pair<int, Eigen::VectorXd>> rows;
  for (int r = 0; r < e.rows(); ++r) {
    Eigen::VectorXd v = e.row(r).transpose();
    int first = n;
    for (int i = n - 1; i >= 0; --i) {
      if (std::abs(v[i]) < 1e-10) v[i] = 0;
      if (v[i] != 0) first = i;
    }
    rows.emplace_back(first, v);
  }
  std::stable_sort(rows.begin(), rows.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [first, v] : rows) {
    out.readable.push_back(v);
    out.invariances.push_back(Relation(setup, p, v));
  }
  return out;
}

}  // namespace ringid::internal
