// The refinement (estimation/modal_refine.h): one Ceres residual block per
// function, all sharing the poles' block; Levenberg-Marquardt with the dense
// Schur complement, which eliminates each function's own block.
#include "estimation/modal_refine.h"

#include <algorithm>
#include <memory>
#include <string>

#include <Eigen/Dense>
#include <ceres/ceres.h>

#include "estimation/modal_refine_internal.h"
#include "estimation/options.h"

namespace ringid {
namespace internal {

using Complex = std::complex<double>;

RefinedFunctionData FunctionData(const Frf& frf, int function, const std::vector<int>& lines,
                                 bool weighted) {
  const FrfFunction& f = frf.functions[function];
  RefinedFunctionData d;
  d.order = static_cast<int>(frf.outputs[f.output].quantity);  // as Lsfd's
  for (int l : lines) {
    const Complex s(0, 2 * M_PI * frf.frequencies_hz[l]);
    d.s.push_back(s);
    d.upper_basis.push_back(std::pow(s, d.order));
    d.lower_basis.push_back(d.upper_basis.back() / (s * s));
    d.h.push_back(f.h[l]);
    d.weight.push_back(weighted ? 1 / f.sigma[l] : 1.0);
  }
  return d;
}

namespace {

// 1 / z, without the overflow guards of the library's complex division.
Complex Inverse(Complex z) { return std::conj(z) / std::norm(z); }

// Row 2k and 2k + 1, column c of a row-major Jacobian with `cols` columns:
// the real and imaginary part of z.
void Put(double* jacobian, int cols, size_t k, int c, Complex z) {
  jacobian[2 * k * cols + c] = z.real();
  jacobian[(2 * k + 1) * cols + c] = z.imag();
}

}  // namespace

// H = sum_r [R a + conj(R) b] + lower s^q / s² + upper s^q, a = 1 / (s - λ),
// b = 1 / (s - conj λ): dH/dλ = R a², dH/d(conj λ) = conj(R) b²; λ = -e^u +
// i e^v moves by Re λ along u and i Im λ along v (its conjugate by the
// conjugates); dH/d Re R = a + b, dH/d Im R = i (a - b). A real pole's term
// Q c, c = 1 / (s - σ), σ = -e^u: dH/du = Q c² σ, dH/dQ = c.
void FunctionResiduals(const RefinedFunctionData& f, int m, const double* poles,
                       const double* own, double* residuals, double* jacobian_poles,
                       double* jacobian_own, int mr) {
  const int np = 2 * m + mr, no = 2 * m + mr + 2;
  std::vector<Complex> lambda(m), residue(m);
  for (int r = 0; r < m; ++r) {
    lambda[r] = Complex(-std::exp(poles[2 * r]), std::exp(poles[2 * r + 1]));
    residue[r] = Complex(own[2 * r], own[2 * r + 1]);
  }
  std::vector<double> sigma(mr);
  for (int j = 0; j < mr; ++j) sigma[j] = -std::exp(poles[2 * m + j]);
  const double lower = own[2 * m + mr], upper = own[2 * m + mr + 1];
  for (size_t k = 0; k < f.s.size(); ++k) {
    const Complex s = f.s[k];
    const double w = f.weight[k];
    Complex h = lower * f.lower_basis[k] + upper * f.upper_basis[k];
    for (int r = 0; r < m; ++r) {
      const Complex a = Inverse(s - lambda[r]), b = Inverse(s - std::conj(lambda[r]));
      const Complex ra = residue[r] * a, rb = std::conj(residue[r]) * b;
      h += ra + rb;
      if (jacobian_poles) {
        Put(jacobian_poles, np, k, 2 * r, w * (ra * a + rb * b) * lambda[r].real());
        Put(jacobian_poles, np, k, 2 * r + 1,
            w * (ra * a - rb * b) * Complex(0, lambda[r].imag()));
      }
      if (jacobian_own) {
        Put(jacobian_own, no, k, 2 * r, w * (a + b));
        Put(jacobian_own, no, k, 2 * r + 1, w * Complex(0, 1) * (a - b));
      }
    }
    for (int j = 0; j < mr; ++j) {
      const Complex c = Inverse(s - sigma[j]), qc = own[2 * m + j] * c;
      h += qc;
      if (jacobian_poles) Put(jacobian_poles, np, k, 2 * m + j, w * qc * c * sigma[j]);
      if (jacobian_own) Put(jacobian_own, no, k, 2 * m + j, w * c);
    }
    if (jacobian_own) {
      Put(jacobian_own, no, k, 2 * m + mr, w * f.lower_basis[k]);
      Put(jacobian_own, no, k, 2 * m + mr + 1, w * f.upper_basis[k]);
    }
    residuals[2 * k] = w * (h - f.h[k]).real();
    residuals[2 * k + 1] = w * (h - f.h[k]).imag();
  }
}

namespace {

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

class FunctionCost : public ceres::CostFunction {
 public:
  FunctionCost(const RefinedFunctionData* f, int m, int mr) : f_(f), m_(m), mr_(mr) {
    set_num_residuals(2 * static_cast<int>(f->s.size()));
    mutable_parameter_block_sizes()->push_back(2 * m + mr);
    mutable_parameter_block_sizes()->push_back(2 * m + mr + 2);
  }
  bool Evaluate(double const* const* x, double* residuals, double** jacobians) const override {
    FunctionResiduals(*f_, m_, x[0], x[1], residuals, jacobians ? jacobians[0] : nullptr,
                      jacobians ? jacobians[1] : nullptr, mr_);
    return Eigen::Map<const Eigen::VectorXd>(residuals, num_residuals()).allFinite();
  }

 private:
  const RefinedFunctionData* f_;
  const int m_, mr_;
};

// The problem's coordinates: the poles' and each function's own.
struct Coordinates {
  Eigen::VectorXd poles;
  std::vector<Eigen::VectorXd> own;
};

// Why the input cannot be refined, or empty.
std::string Refusal(const Frf& frf, const std::vector<int>& lines,
                    const std::vector<Complex>& poles, const std::vector<double>& real_poles,
                    const std::vector<LsfdFunction>& start) {
  if (poles.empty()) return "no poles to refine";
  for (size_t r = 0; r < poles.size(); ++r) {
    if (!(poles[r].real() < 0 && poles[r].imag() > 0)) {
      return "pole " + std::to_string(r) + " has not Re < 0 < Im";
    }
  }
  for (size_t j = 0; j < real_poles.size(); ++j) {
    if (!(real_poles[j] < 0)) return "real pole " + std::to_string(j) + " is not negative";
  }
  if (start.size() != frf.functions.size()) return "the start has not one function per FRF";
  for (size_t f = 0; f < start.size(); ++f) {
    if (start[f].residues.size() != poles.size() ||
        start[f].real_residues.size() != real_poles.size()) {
      return "the start has not one residue per pole";
    }
    bool finite = std::isfinite(start[f].lower) && std::isfinite(start[f].upper);
    for (const Complex& r : start[f].residues) finite = finite && std::isfinite(std::abs(r));
    for (const double q : start[f].real_residues) finite = finite && std::isfinite(q);
    if (!finite) return "the start of function " + std::to_string(f) + " is not finite";
  }
  if (lines.empty()) return "no lines";
  for (int l : lines) {
    if (l < 0 || l >= static_cast<int>(frf.frequencies_hz.size())) return "a line out of range";
  }
  return "";
}

// Every function has a positive sigma at each line.
bool AllSigmas(const Frf& frf, const std::vector<int>& lines) {
  for (const FrfFunction& f : frf.functions) {
    if (f.sigma.size() != f.h.size()) return false;
    for (int l : lines) {
      if (!(f.sigma[l] > 0)) return false;
    }
  }
  return true;
}

// Levenberg-Marquardt from x (changed in place); Ceres' summary.
ceres::Solver::Summary Solve(const std::vector<RefinedFunctionData>& data, int m, int mr,
                             Coordinates* x) {
  ceres::Problem problem;
  auto ordering = std::make_shared<ceres::ParameterBlockOrdering>();
  for (size_t f = 0; f < data.size(); ++f) {
    problem.AddResidualBlock(new FunctionCost(&data[f], m, mr), nullptr, x->poles.data(),
                             x->own[f].data());
    ordering->AddElementToGroup(x->own[f].data(), 0);  // eliminated first
  }
  ordering->AddElementToGroup(x->poles.data(), 1);
  ceres::Solver::Options so;
  so.minimizer_type = ceres::TRUST_REGION;
  so.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  so.linear_solver_type = ceres::DENSE_SCHUR;
  so.linear_solver_ordering = ordering;
  so.max_num_iterations = 100;
  // A relative change of 1e-10: far below one unit of chi-square at any
  // size of these problems (about 3e-6 for 28 FRFs x 491 lines).
  so.function_tolerance = 1e-10;
  so.gradient_tolerance = 1e-12;
  so.parameter_tolerance = 1e-14;
  so.logging_type = ceres::SILENT;
  so.num_threads = 1;
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  return summary;
}

// The poles' covariance in their coordinates (see the header), and whether
// each coordinate is determined (outside the null space).
void PoleCovariance(const std::vector<RefinedFunctionData>& data, int m, int mr,
                    const Coordinates& x, Eigen::MatrixXd* covariance,
                    std::vector<bool>* determined) {
  const int np = 2 * m + mr, no = 2 * m + mr + 2;
  int rows = 0;
  for (const RefinedFunctionData& f : data) rows += 2 * static_cast<int>(f.s.size());
  Eigen::MatrixXd stacked(rows, np);
  int at = 0;
  for (size_t f = 0; f < data.size(); ++f) {
    const int n = 2 * static_cast<int>(data[f].s.size());
    RowMajor jp(n, np), jo(n, no);
    Eigen::VectorXd r(n);
    FunctionResiduals(data[f], m, x.poles.data(), x.own[f].data(), r.data(), jp.data(), jo.data(),
                      mr);
    // The part of jp off the span of the own columns (to unit norm first:
    // the residual terms differ from the residues' by powers of ω).
    const Eigen::VectorXd scale = jo.colwise().norm().cwiseMax(1e-300).cwiseInverse();
    const Eigen::MatrixXd scaled = jo * scale.asDiagonal();
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(scaled);
    stacked.middleRows(at, n) = jp - scaled * qr.solve(jp);
    at += n;
  }
  // Its SVD through its QR's R (the same singular values and V).
  const Eigen::MatrixXd triangle = Eigen::HouseholderQR<Eigen::MatrixXd>(stacked)
                                       .matrixQR()
                                       .topRows(np)
                                       .triangularView<Eigen::Upper>();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(triangle, Eigen::ComputeFullV);
  const Eigen::VectorXd& s = svd.singularValues();
  int rank = 0;
  while (rank < np && s(rank) > UncertaintyOptions{}.rank_tolerance * s(0)) ++rank;
  const Eigen::MatrixXd v = svd.matrixV().leftCols(rank);
  *covariance = v * s.head(rank).array().square().inverse().matrix().asDiagonal() * v.transpose();
  determined->assign(np, true);
  for (int i = 0; i < np; ++i) {
    (*determined)[i] = svd.matrixV().row(i).tail(np - rank).norm() < 1e-6;
  }
}

// The refined poles with their standard errors from `covariance` (scaled
// by `scale`): f = e^v / 2π and ζ = e^u / |λ| have df = f dv and dζ = ζ(1 -
// ζ²)(du - dv).
std::vector<RefinedPole> Poles(const Coordinates& x, int m, const Eigen::MatrixXd& covariance,
                               const std::vector<bool>& determined, double scale) {
  std::vector<RefinedPole> out;
  for (int r = 0; r < m; ++r) {
    RefinedPole p;
    p.eigenvalue = Complex(-std::exp(x.poles(2 * r)), std::exp(x.poles(2 * r + 1)));
    p.frequency_hz = p.eigenvalue.imag() / (2 * M_PI);
    p.damping_ratio = -p.eigenvalue.real() / std::abs(p.eigenvalue);
    if (determined[2 * r] && determined[2 * r + 1]) {
      const Eigen::Matrix2d c = scale * covariance.block<2, 2>(2 * r, 2 * r);
      const double z = p.damping_ratio * (1 - p.damping_ratio * p.damping_ratio);
      const Eigen::Vector2d df(0, p.frequency_hz), dz(z, -z);
      p.frequency_std_hz = std::sqrt(df.dot(c * df));
      p.damping_ratio_std = std::sqrt(dz.dot(c * dz));
    }
    out.push_back(p);
  }
  return out;
}

}  // namespace
}  // namespace internal

void RefineModes(const Frf& frf, const std::vector<int>& lines,
                 const std::vector<std::complex<double>>& poles,
                 const std::vector<double>& real_poles, const std::vector<LsfdFunction>& start,
                 bool weigh_by_sigma, ModalRefinement* out) {
  using namespace internal;
  *out = ModalRefinement{};
  RefinementFit& fit = out->fit;
  const std::string refusal = Refusal(frf, lines, poles, real_poles, start);
  if (!refusal.empty()) {
    fit.status = Status::InvalidInput(refusal);
    return;
  }
  const int m = static_cast<int>(poles.size()), nf = static_cast<int>(frf.functions.size());
  const int mr = static_cast<int>(real_poles.size());
  fit.weighted = weigh_by_sigma && AllSigmas(frf, lines);
  fit.degrees_of_freedom =
      2 * static_cast<int>(lines.size()) * nf - (2 * m + mr) - nf * (2 * m + mr + 2);
  if (fit.degrees_of_freedom <= 0) {
    fit.status = Status::InvalidInput("more coordinates than values: no degrees of freedom");
    return;
  }
  std::vector<RefinedFunctionData> data;
  Coordinates x;
  x.poles.resize(2 * m + mr);
  for (int r = 0; r < m; ++r) {
    x.poles(2 * r) = std::log(-poles[r].real());
    x.poles(2 * r + 1) = std::log(poles[r].imag());
  }
  for (int j = 0; j < mr; ++j) x.poles(2 * m + j) = std::log(-real_poles[j]);
  for (int f = 0; f < nf; ++f) {
    data.push_back(FunctionData(frf, f, lines, fit.weighted));
    Eigen::VectorXd own(2 * m + mr + 2);
    for (int r = 0; r < m; ++r) {
      own.segment<2>(2 * r) << start[f].residues[r].real(), start[f].residues[r].imag();
    }
    for (int j = 0; j < mr; ++j) own(2 * m + j) = start[f].real_residues[j];
    own.tail<2>() << start[f].lower, start[f].upper;
    x.own.push_back(own);
  }
  const ceres::Solver::Summary summary = Solve(data, m, mr, &x);
  fit.iterations = summary.num_successful_steps + summary.num_unsuccessful_steps;
  if (!summary.IsSolutionUsable() || summary.termination_type == ceres::NO_CONVERGENCE) {
    fit.status = Status::Failed("the refinement did not converge: " + summary.message);
    return;
  }
  fit.chi_square = 2 * summary.final_cost;
  Eigen::MatrixXd covariance;
  std::vector<bool> determined;
  PoleCovariance(data, m, mr, x, &covariance, &determined);
  out->poles = Poles(x, m, covariance, determined,
                     fit.weighted ? 1.0 : fit.chi_square / fit.degrees_of_freedom);
  const auto [low, high] = std::minmax_element(lines.begin(), lines.end());
  for (int j = 0; j < mr; ++j) out->real_poles.push_back(-std::exp(x.poles(2 * m + j)));
  for (size_t r = 0; r < out->poles.size(); ++r) {
    const double hz = out->poles[r].frequency_hz;
    if (!(hz >= frf.frequencies_hz[*low] && hz <= frf.frequencies_hz[*high])) {
      fit.status = Status::Failed("pole " + std::to_string(r) + " left the band for " +
                                  std::to_string(hz) + " Hz");
      return;
    }
  }
  for (int f = 0; f < nf; ++f) {
    LsfdFunction g = start[f];
    for (int r = 0; r < m; ++r) g.residues[r] = Complex(x.own[f](2 * r), x.own[f](2 * r + 1));
    for (int j = 0; j < mr; ++j) g.real_residues[j] = x.own[f](2 * m + j);
    g.lower = x.own[f](2 * m + mr);
    g.upper = x.own[f](2 * m + mr + 1);
    out->functions.push_back(std::move(g));
  }
  fit.status = Status::Success("converged in " + std::to_string(fit.iterations) +
                               " iterations");
}

}  // namespace ringid
