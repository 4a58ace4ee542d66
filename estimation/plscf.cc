// pLSCF, its stabilisation diagram and the physical poles
// (estimation/plscf.h). The normal matrices are Toeplitz in the lag between
// basis orders (|z| = 1 on the lines), so that each is built from 2n + 1 sums
// over the lines, and the reduced matrix of order n is the leading block of
// the largest order's: the Cholesky factor of a leading block of R_o is the
// leading block of its factor, so with Y_o = L_o^-1 S_o,
// M_n = T_n - sum_o sum_{j <= n} y_oj^T y_oj, over the leading columns.
#include "estimation/plscf.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <utility>

#include <Eigen/Dense>

#include "estimation/plscf_internal.h"

namespace ringid {
namespace {

using Complex = std::complex<double>;

bool Fail(std::string* why, std::string text) {
  *why = std::move(text);
  return false;
}

// Each output's row of H per line (lines x inputs) and its weight per line.
struct OutputRows {
  std::vector<Eigen::MatrixXcd> h;
  std::vector<Eigen::VectorXd> weight;
};

// The blocks (estimation/plscf.h): the connected parts of the measured
// pairs (an output joins the inputs it is measured at); in each, the outputs
// measured at all its inputs, else one block per set of its inputs measured
// at the same outputs. An input without a function is in none.
std::vector<PlscfBlock> Blocks(const Frf& frf) {
  const int ni = static_cast<int>(frf.inputs.size()), no = static_cast<int>(frf.outputs.size());
  std::vector<std::vector<bool>> at(no, std::vector<bool>(ni, false));
  for (const FrfFunction& f : frf.functions) at[f.output][f.input] = true;
  std::vector<int> part(ni);
  for (int i = 0; i < ni; ++i) part[i] = i;
  const auto root = [&](int i) {
    while (part[i] != i) i = part[i] = part[part[i]];
    return i;
  };
  for (int o = 0; o < no; ++o) {
    const int first = static_cast<int>(std::find(at[o].begin(), at[o].end(), true) - at[o].begin());
    for (int i = first + 1; i < ni; ++i) {
      if (at[o][i]) part[root(i)] = root(first);
    }
  }
  const auto outputs_at = [&](const std::vector<int>& inputs) {
    std::vector<int> outputs;
    for (int o = 0; o < no; ++o) {
      if (std::all_of(inputs.begin(), inputs.end(), [&](int i) { return at[o][i]; })) outputs.push_back(o);
    }
    return outputs;
  };
  std::vector<PlscfBlock> blocks;
  for (int r = 0; r < ni; ++r) {
    std::vector<int> inputs;
    for (int i = 0; i < ni; ++i) {
      if (root(i) == r && std::any_of(at.begin(), at.end(), [&](const auto& row) { return row[i]; })) {
        inputs.push_back(i);
      }
    }
    if (inputs.empty()) continue;
    PlscfBlock whole{inputs, outputs_at(inputs), {}};
    if (!whole.outputs.empty()) {
      blocks.push_back(std::move(whole));
      continue;
    }
    for (size_t k = 0; k < inputs.size(); ++k) {
      const std::vector<int> outputs = outputs_at({inputs[k]});
      if (std::any_of(blocks.begin(), blocks.end(), [&](const PlscfBlock& b) {
            return b.outputs == outputs && root(b.inputs[0]) == r;
          })) {
        continue;  // grouped with an earlier input
      }
      PlscfBlock same{{}, outputs, {}};
      for (size_t j = k; j < inputs.size(); ++j) {
        if (outputs_at({inputs[j]}) == outputs) same.inputs.push_back(inputs[j]);
      }
      blocks.push_back(std::move(same));
    }
  }
  return blocks;
}

// The block's outputs, with their rows over `lines` on its inputs.
OutputRows BlockRows(const Frf& frf, const PlscfBlock& block, const std::vector<int>& lines,
                     bool weigh) {
  const int ni = static_cast<int>(block.inputs.size()), nl = static_cast<int>(lines.size());
  std::vector<std::vector<const FrfFunction*>> at(frf.outputs.size(),
                                                  std::vector<const FrfFunction*>(frf.inputs.size()));
  for (const FrfFunction& f : frf.functions) at[f.output][f.input] = &f;
  OutputRows rows;
  for (const int o : block.outputs) {
    Eigen::MatrixXcd h(nl, ni);
    Eigen::VectorXd mean_square = Eigen::VectorXd::Zero(nl);
    bool sigmas = weigh;
    for (int i = 0; i < ni; ++i) {
      const FrfFunction& f = *at[o][block.inputs[i]];
      sigmas = sigmas && f.sigma.size() == f.h.size();
      for (int k = 0; sigmas && k < nl; ++k) sigmas = f.sigma[lines[k]] > 0;  // as Lsfd's
      for (int k = 0; k < nl; ++k) {
        h(k, i) = f.h[lines[k]];
        if (sigmas) mean_square(k) += f.sigma[lines[k]] * f.sigma[lines[k]] / ni;
      }
    }
    rows.h.push_back(std::move(h));
    rows.weight.push_back(sigmas ? Eigen::VectorXd(mean_square.cwiseSqrt().cwiseInverse())
                                 : Eigen::VectorXd::Ones(nl));
  }
  return rows;
}

// The normal equations of the largest order, as the Toeplitz sums give them:
// per output the Cholesky-whitened Y_o = L_o^-1 S_o, and T = sum_o T_o.
struct Normal {
  std::vector<Eigen::MatrixXd> y;
  Eigen::MatrixXd t;
};

bool BuildNormal(const OutputRows& rows, const Eigen::VectorXd& theta, int n, Normal* normal) {
  const int nl = static_cast<int>(theta.size()), ni = static_cast<int>(rows.h[0].cols());
  const int no = static_cast<int>(rows.h.size());
  // Per line the sums' terms: per output w², -w² H_i; then sum_o w² conj(H_i) H_i'.
  const int per = 1 + ni, t_col = no * per;
  Eigen::MatrixXcd q = Eigen::MatrixXcd::Zero(nl, t_col + ni * ni);
  for (int o = 0; o < no; ++o) {
    const Eigen::VectorXd w2 = rows.weight[o].array().square();
    q.col(o * per) = w2.cast<Complex>();
    for (int i = 0; i < ni; ++i)
      q.col(o * per + 1 + i) = -(w2.cast<Complex>().cwiseProduct(rows.h[o].col(i)));
    for (int i = 0; i < ni; ++i) {
      for (int k = 0; k < ni; ++k) {
        q.col(t_col + i * ni + k) += w2.cast<Complex>().cwiseProduct(
            rows.h[o].col(i).conjugate().cwiseProduct(rows.h[o].col(k)));
      }
    }
  }
  // Re sum_k z_k^d q_k with z = exp(-iθ): cos(dθ) Re q + sin(dθ) Im q, and
  // at lag -d the sine's sign turned.
  Eigen::MatrixXd c(n + 1, nl), s(n + 1, nl);
  for (int d = 0; d <= n; ++d) {
    c.row(d) = (d * theta).array().cos().transpose();
    s.row(d) = (d * theta).array().sin().transpose();
  }
  const Eigen::MatrixXd p1 = c * q.real(), p2 = s * q.imag();
  auto seq = [&](int col, int lag) {
    return lag >= 0 ? p1(lag, col) + p2(lag, col) : p1(-lag, col) - p2(-lag, col);
  };
  const int m = (n + 1) * ni;
  normal->t.resize(m, m);
  for (int j = 0; j <= n; ++j) {
    for (int l = 0; l <= n; ++l) {
      for (int i = 0; i < ni; ++i) {
        for (int k = 0; k < ni; ++k)
          normal->t(j * ni + i, l * ni + k) = seq(t_col + i * ni + k, l - j);
      }
    }
  }
  normal->y.clear();
  for (int o = 0; o < no; ++o) {
    Eigen::MatrixXd r(n + 1, n + 1), so(n + 1, m);
    for (int j = 0; j <= n; ++j) {
      for (int l = 0; l <= n; ++l) {
        r(j, l) = seq(o * per, l - j);
        for (int i = 0; i < ni; ++i) so(j, l * ni + i) = seq(o * per + 1 + i, l - j);
      }
    }
    const Eigen::LLT<Eigen::MatrixXd> llt(r);
    if (llt.info() != Eigen::Success) return false;
    normal->y.push_back(llt.matrixL().solve(so));
  }
  return true;
}

// The participation: the null vector of A(x)^T = sum_j alpha_j^T x^j
// (alpha_n = I), evaluated in 1/x beyond the unit circle; unit norm, its
// largest component real and positive.
Eigen::VectorXcd Participation(const std::vector<Eigen::MatrixXd>& alpha, Complex x) {
  const int n = static_cast<int>(alpha.size()), ni = static_cast<int>(alpha[0].rows());
  const Eigen::MatrixXcd identity = Eigen::MatrixXcd::Identity(ni, ni);
  Eigen::MatrixXcd p;
  if (std::abs(x) <= 1) {
    p = identity;
    for (int j = n - 1; j >= 0; --j) p = p * x + alpha[j].transpose().cast<Complex>();
  } else {
    const Complex y = 1.0 / x;
    p = alpha[0].transpose().cast<Complex>();
    for (int j = 1; j < n; ++j) p = p * y + alpha[j].transpose().cast<Complex>();
    p = p * y + identity;
  }
  Eigen::VectorXcd u = Eigen::VectorXcd::Ones(1);
  if (ni > 1) u = Eigen::JacobiSVD<Eigen::MatrixXcd>(p, Eigen::ComputeFullV).matrixV().col(ni - 1);
  Eigen::Index largest;
  u.cwiseAbs().maxCoeff(&largest);
  return u * (std::abs(u(largest)) / u(largest)) / u.norm();
}

// The poles of order n from the reduced normal matrix M (leading
// (n + 1) x inputs block), A monic.
bool PolesOfOrder(const Eigen::MatrixXd& m, int n, int ni, double dt, PlscfOrder* order) {
  const int a = n * ni;
  Eigen::LDLT<Eigen::MatrixXd> ldlt(m.topLeftCorner(a, a));
  if (ldlt.info() != Eigen::Success) return false;
  const Eigen::MatrixXd low = -ldlt.solve(m.block(0, a, a, ni));
  if (!low.allFinite()) return false;
  std::vector<Eigen::MatrixXd> alpha(n);
  for (int j = 0; j < n; ++j) alpha[j] = low.middleRows(j * ni, ni);
  // The companion of the transposed polynomial: first block row
  // [-alpha_{n-1}^T ... -alpha_0^T], identities below the diagonal.
  Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(a, a);
  for (int k = 0; k < n; ++k) companion.block(0, k * ni, ni, ni) = -alpha[n - 1 - k].transpose();
  companion.block(ni, 0, a - ni, a - ni).setIdentity();
  const Eigen::EigenSolver<Eigen::MatrixXd> eigen(companion, false);
  if (eigen.info() != Eigen::Success) return false;
  order->order = n;
  order->poles.clear();
  order->real_poles.clear();
  for (const Complex& x : eigen.eigenvalues()) {
    if (x.imag() == 0 && x.real() > 0) {  // a real root (a real Schur block of one)
      PlscfPole pole;
      pole.eigenvalue = -std::log(x.real()) / dt;
      pole.participation = Participation(alpha, x);
      order->real_poles.push_back(std::move(pole));
      continue;
    }
    if (!(x.imag() < 0)) continue;  // Im λ > 0: one of each pair
    PlscfPole pole;
    pole.eigenvalue = -std::log(x) / dt;
    pole.frequency_hz = pole.eigenvalue.imag() / (2 * M_PI);
    pole.damping_ratio = -pole.eigenvalue.real() / std::abs(pole.eigenvalue);
    pole.participation = Participation(alpha, x);
    order->poles.push_back(std::move(pole));
  }
  std::sort(order->poles.begin(), order->poles.end(),
            [](const PlscfPole& p, const PlscfPole& q) { return p.frequency_hz < q.frequency_hz; });
  return true;
}

double Mac(const Eigen::VectorXcd& a, const Eigen::VectorXcd& b) {
  return std::norm(a.dot(b)) / (a.squaredNorm() * b.squaredNorm());
}

// Each real pole's flags against the nearest real pole of the order below.
void MarkRealStable(const PlscfOptions& o, const PlscfOrder& below, PlscfOrder* order) {
  for (PlscfPole& p : order->real_poles) {
    const PlscfPole* near = nullptr;
    for (const PlscfPole& q : below.real_poles) {
      if (!near || std::abs(q.eigenvalue - p.eigenvalue) < std::abs(near->eigenvalue - p.eigenvalue)) {
        near = &q;
      }
    }
    if (!near) continue;
    p.stable_frequency =
        std::abs(p.eigenvalue - near->eigenvalue) <= o.stable_frequency * std::abs(p.eigenvalue);
    p.stable_damping = true;  // a real root has no damping ratio of its own
    p.stable_vector = Mac(p.participation, near->participation) >= o.stable_mac;
  }
}

// Each pole's flags against the nearest pole (in λ) of the order below.
void MarkStable(const PlscfOptions& o, const PlscfOrder& below, PlscfOrder* order) {
  MarkRealStable(o, below, order);
  for (PlscfPole& p : order->poles) {
    const PlscfPole* near = nullptr;
    for (const PlscfPole& q : below.poles) {
      if (!near ||
          std::norm(q.eigenvalue - p.eigenvalue) < std::norm(near->eigenvalue - p.eigenvalue)) {
        near = &q;
      }
    }
    if (!near) continue;
    p.stable_frequency =
        std::abs(p.frequency_hz - near->frequency_hz) <= o.stable_frequency * p.frequency_hz;
    p.stable_damping = std::abs(p.damping_ratio - near->damping_ratio) <=
                       o.stable_damping * std::abs(p.damping_ratio);
    p.stable_vector = Mac(p.participation, near->participation) >= o.stable_mac;
  }
}

}  // namespace

namespace plscf_internal {

// The physical poles: repeatedly, the stable pole (positive damping, in
// [low_hz, high_hz]) whose window (the stability tolerances around it) holds
// stable poles of the most orders; its cluster is the nearest of each order
// in the window, and its pole that of the highest order.

std::vector<ExtractedMode> ChoosePoles(const PlscfOptions& o,
                                       const std::vector<PlscfOrder>& diagram, double low_hz,
                                       double high_hz, bool settled_damping) {
  struct Candidate {
    int order;  // index into diagram
    const PlscfPole* pole;
  };
  std::vector<Candidate> stable;
  for (int k = 0; k < static_cast<int>(diagram.size()); ++k) {
    for (const PlscfPole& p : diagram[k].poles) {
      const bool held = settled_damping ? p.stable() : p.stable_frequency && p.stable_vector;
      if (held && p.damping_ratio > 0 && p.frequency_hz >= low_hz && p.frequency_hz <= high_hz) {
        stable.push_back({k, &p});
      }
    }
  }
  auto in_window = [&](const PlscfPole& centre, const PlscfPole& p) {
    return std::abs(p.frequency_hz - centre.frequency_hz) <=
               o.stable_frequency * centre.frequency_hz &&
           std::abs(p.damping_ratio - centre.damping_ratio) <=
               o.stable_damping * centre.damping_ratio;
  };
  // The nearest pole of each order within the window of `centre`.
  auto cluster = [&](const PlscfPole& centre) {
    std::vector<int> nearest(diagram.size(), -1);
    for (int c = 0; c < static_cast<int>(stable.size()); ++c) {
      const Candidate& q = stable[c];
      if (!q.pole || !in_window(centre, *q.pole)) continue;
      int& best = nearest[q.order];
      if (best < 0 || std::norm(q.pole->eigenvalue - centre.eigenvalue) <
                          std::norm(stable[best].pole->eigenvalue - centre.eigenvalue)) {
        best = c;
      }
    }
    nearest.erase(std::remove(nearest.begin(), nearest.end(), -1), nearest.end());
    return nearest;
  };
  std::vector<ExtractedMode> modes;
  for (;;) {
    std::vector<int> best;
    for (const Candidate& c : stable) {
      if (!c.pole) continue;
      std::vector<int> members = cluster(*c.pole);
      if (members.size() > best.size()) best = std::move(members);
    }
    if (static_cast<int>(best.size()) < o.min_stable_orders) break;
    const Candidate top = stable[best.back()];  // ascending order
    for (int c : best) stable[c].pole = nullptr;
    // A lightly damped mode's damping wanders across orders by more than
    // the window: its remainder, at the same frequency with the same
    // participation, is not another mode.
    if (std::any_of(modes.begin(), modes.end(), [&](const ExtractedMode& m) {
          return std::abs(m.frequency_hz - top.pole->frequency_hz) <=
                     o.stable_frequency * m.frequency_hz &&
                 Mac(m.participation, top.pole->participation) >= o.stable_mac;
        })) {
      continue;
    }
    ExtractedMode mode;
    mode.eigenvalue = top.pole->eigenvalue;
    mode.frequency_hz = top.pole->frequency_hz;
    mode.damping_ratio = top.pole->damping_ratio;
    mode.participation = top.pole->participation;
    mode.order = diagram[top.order].order;
    mode.stable_orders = static_cast<int>(best.size());
    modes.push_back(std::move(mode));
  }
  std::sort(modes.begin(), modes.end(), [](const ExtractedMode& a, const ExtractedMode& b) {
    return a.frequency_hz < b.frequency_hz;
  });
  return modes;
}

// A block's mode with its participation on all the Frf's inputs (0 on those
// outside the block).
void OnAllInputs(const Frf& frf, const PlscfBlock& b, ExtractedMode* m) {
  Eigen::VectorXcd l = Eigen::VectorXcd::Zero(frf.inputs.size());
  for (size_t i = 0; i < b.inputs.size(); ++i) l(b.inputs[i]) = m->participation(i);
  m->participation = std::move(l);
}

// Two real poles are one where they lie within stable_frequency of `b`.
bool SameRealPole(const PlscfOptions& o, double a, double b) {
  return std::abs(a - b) <= o.stable_frequency * std::abs(b);
}

// The physical real poles: repeatedly, the stable real pole (negative, its
// |σ| / 2π at most high_hz: one below the band leaves a 1 / s term in it,
// which neither residual term is) that the most orders hold within
// stable_frequency (relative), taken at its highest order; one near a pole
// already taken is that pole again.
std::vector<double> ChooseRealPoles(const PlscfOptions& o, const std::vector<PlscfOrder>& diagram,
                                    double high_hz) {
  std::vector<std::pair<int, double>> stable;  // (order index, σ)
  for (int k = 0; k < static_cast<int>(diagram.size()); ++k) {
    for (const PlscfPole& p : diagram[k].real_poles) {
      const double sigma = p.eigenvalue.real(), corner_hz = -sigma / (2 * M_PI);
      if (p.stable() && sigma < 0 && corner_hz <= high_hz) {
        stable.emplace_back(k, sigma);
      }
    }
  }
  const auto near = [&](double a, double b) { return SameRealPole(o, a, b); };
  std::vector<double> out;
  std::vector<bool> used(stable.size(), false);
  for (;;) {
    std::vector<int> best;
    for (size_t c = 0; c < stable.size(); ++c) {
      if (used[c]) continue;
      std::vector<int> members;  // the nearest of each order
      for (size_t q = 0; q < stable.size(); ++q) {
        if (used[q] || !near(stable[q].second, stable[c].second)) continue;
        const auto same_order = std::find_if(members.begin(), members.end(), [&](int i) {
          return stable[i].first == stable[q].first;
        });
        if (same_order == members.end()) members.push_back(static_cast<int>(q));
        else if (std::abs(stable[q].second - stable[c].second) < std::abs(stable[*same_order].second - stable[c].second)) *same_order = static_cast<int>(q);
      }
      if (members.size() > best.size()) best = std::move(members);
    }
    if (static_cast<int>(best.size()) < o.min_stable_orders) break;
    int top = best[0];
    for (int i : best) {
      used[i] = true;
      if (stable[i].first > stable[top].first) top = i;
    }
    const double sigma = stable[top].second;
    if (std::none_of(out.begin(), out.end(), [&](double s) { return near(sigma, s); })) out.push_back(sigma);
  }
  std::sort(out.begin(), out.end(), std::greater<double>());  // ascending |σ|
  return out;
}

// Each mode's residues from LSFD and its shape on the outputs: psi = R
// conj(l) / |l|² over the inputs measured.
void AddResidues(const Frf& frf, const std::vector<LsfdFunction>& functions,
                 std::vector<ExtractedMode>* modes) {
  const int no = static_cast<int>(frf.outputs.size()), ni = static_cast<int>(frf.inputs.size());
  for (size_t r = 0; r < modes->size(); ++r) {
    ExtractedMode& mode = (*modes)[r];
    mode.residues = Eigen::MatrixXcd::Constant(no, ni, Complex(NAN, NAN));
    Eigen::VectorXcd sum = Eigen::VectorXcd::Zero(no);
    Eigen::VectorXd weight = Eigen::VectorXd::Zero(no);
    for (const LsfdFunction& f : functions) {
      const Complex l = mode.participation(f.input);
      mode.residues(f.output, f.input) = f.residues[r];
      sum(f.output) += f.residues[r] * std::conj(l);
      weight(f.output) += std::norm(l);
    }
    mode.shape = Eigen::VectorXcd::Zero(no);  // 0 where no input of its participation is measured
    for (int o = 0; o < no; ++o) {
      if (weight(o) > 0) mode.shape(o) = sum(o) / weight(o);
    }
  }
}

// The modes and functions refined (estimation/modal_refine.h), the modes
// kept in ascending frequency with their residues; untouched where the
// refinement fails.
void Refine(const Frf& frf, bool weigh_by_sigma, PlscfResult* r) {
  std::vector<Complex> poles;
  for (const ExtractedMode& mode : r->modes) poles.push_back(mode.eigenvalue);
  ModalRefinement refined;
  RefineModes(frf, r->lines, poles, r->real_poles, r->functions, weigh_by_sigma, &refined);
  r->refinement = refined.fit;
  if (!refined.fit.status.ok()) return;
  r->real_poles = refined.real_poles;
  std::vector<int> order(poles.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return refined.poles[a].frequency_hz < refined.poles[b].frequency_hz;
  });
  std::vector<ExtractedMode> modes;
  for (int k : order) {
    ExtractedMode mode = r->modes[k];
    const RefinedPole& p = refined.poles[k];
    mode.eigenvalue = p.eigenvalue;
    mode.frequency_hz = p.frequency_hz;
    mode.damping_ratio = p.damping_ratio;
    mode.frequency_std_hz = p.frequency_std_hz;
    mode.damping_ratio_std = p.damping_ratio_std;
    modes.push_back(std::move(mode));
  }
  r->modes = std::move(modes);
  r->functions = std::move(refined.functions);
  for (LsfdFunction& f : r->functions) {
    const std::vector<Complex> residues = f.residues;
    for (size_t k = 0; k < order.size(); ++k) f.residues[k] = residues[order[k]];
  }
}

}  // namespace plscf_internal

namespace {

using namespace plscf_internal;  // NOLINT: this file's own

// One block's diagram, physical poles (their participation on all the
// Frf's inputs, 0 on those outside the block) and real poles.
Status FitBlock(const Frf& frf, const PlscfOptions& o, const std::vector<int>& lines, double dt,
                const Eigen::VectorXd& theta, PlscfBlock* b, std::vector<ExtractedMode>* modes,
                std::vector<double>* real_poles) {
  Normal normal;
  if (!BuildNormal(BlockRows(frf, *b, lines, o.weigh_by_sigma), theta, o.max_order, &normal)) {
    return Status::Failed("pLSCF: a weighted basis is singular (too few distinct lines)");
  }
  const int ni = static_cast<int>(b->inputs.size());
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(normal.t.rows(), normal.t.cols());
  Eigen::MatrixXd yn(normal.y.size(), normal.t.cols());
  for (int n = 0; n <= o.max_order; ++n) {
    for (size_t out = 0; out < normal.y.size(); ++out) yn.row(out) = normal.y[out].row(n);
    k.noalias() += yn.transpose() * yn;
    if (n < o.min_order) continue;
    const int m = (n + 1) * ni;
    PlscfOrder order;
    if (!PolesOfOrder(normal.t.topLeftCorner(m, m) - k.topLeftCorner(m, m), n, ni, dt, &order)) {
      // Noise-free data are singular above their exact order: the diagram
      // ends there where it holds enough orders to call a pole physical.
      if (static_cast<int>(b->diagram.size()) > o.min_stable_orders) break;
      return Status::Failed("pLSCF: the normal equations of order " + std::to_string(n) +
                            " are singular");
    }
    if (!b->diagram.empty()) MarkStable(o, b->diagram.back(), &order);
    b->diagram.push_back(std::move(order));
  }
  const double low_hz = frf.frequencies_hz[lines.front()], high_hz = frf.frequencies_hz[lines.back()];
  *modes = ChoosePoles(o, b->diagram, low_hz, high_hz);
  *real_poles = ChooseRealPoles(o, b->diagram, high_hz);
  for (ExtractedMode& m : *modes) OnAllInputs(frf, *b, &m);
  return Status::Success();
}

}  // namespace

bool PlscfOptions::IsValid(std::string* why) const {
  if (!(min_order >= 1 && max_order >= min_order)) {
    return Fail(why, "orders: need 1 <= min_order <= max_order");
  }
  if (max_order > 1000) return Fail(why, "max_order must be at most 1000");
  if (!(band_low_hz >= 0 && band_high_hz > band_low_hz)) {
    return Fail(why, "band: need 0 <= band_low_hz < band_high_hz");
  }
  if (!(stable_frequency > 0 && stable_damping > 0 && stable_mac > 0 && stable_mac <= 1)) {
    return Fail(why, "stability: need positive tolerances and 0 < stable_mac <= 1");
  }
  if (min_stable_orders < 1) return Fail(why, "min_stable_orders must be at least 1");
  return true;
}

void ExtractModes(const Frf& frf, const PlscfOptions& o, PlscfResult* r) {
  *r = PlscfResult{};
  std::string why;
  if (!o.IsValid(&why)) {
    r->status = Status::InvalidInput(why);
    return;
  }
  for (int l = 0; l < static_cast<int>(frf.frequencies_hz.size()); ++l) {
    const double hz = frf.frequencies_hz[l];
    if (hz > 0 && hz >= o.band_low_hz && hz <= o.band_high_hz) r->lines.push_back(l);
  }
  if (static_cast<int>(r->lines.size()) <= o.max_order) {
    r->status = Status::InvalidInput(
        std::to_string(r->lines.size()) + " lines in the band: max_order " +
        std::to_string(o.max_order) + " needs at least " + std::to_string(o.max_order + 1));
    return;
  }
  r->dt = 1 / (2 * frf.frequencies_hz[r->lines.back()]);
  Eigen::VectorXd theta(r->lines.size());
  for (size_t k = 0; k < r->lines.size(); ++k) {
    theta(k) = 2 * M_PI * frf.frequencies_hz[r->lines[k]] * r->dt;
  }
  r->blocks = Blocks(frf);
  for (PlscfBlock& b : r->blocks) {
    std::vector<ExtractedMode> found;
    std::vector<double> real;
    r->status = FitBlock(frf, o, r->lines, r->dt, theta, &b, &found, &real);
    if (!r->status.ok()) return;
    for (const double sigma : real) {
      if (std::none_of(r->real_poles.begin(), r->real_poles.end(),
                       [&](double q) { return SameRealPole(o, sigma, q); })) {
        r->real_poles.push_back(sigma);
      }
    }
    for (ExtractedMode& m : found) {
      // A pole another block found too (within the stability tolerances):
      // the one held at more orders.
      const auto same = std::find_if(r->modes.begin(), r->modes.end(), [&](const ExtractedMode& q) {
        return std::abs(q.frequency_hz - m.frequency_hz) <= o.stable_frequency * q.frequency_hz &&
               std::abs(q.damping_ratio - m.damping_ratio) <= o.stable_damping * q.damping_ratio;
      });
      if (same == r->modes.end()) r->modes.push_back(std::move(m));
      else if (m.stable_orders > same->stable_orders) *same = std::move(m);
    }
  }
  std::sort(r->modes.begin(), r->modes.end(), [](const ExtractedMode& a, const ExtractedMode& b) {
    return a.frequency_hz < b.frequency_hz;
  });
  std::sort(r->real_poles.begin(), r->real_poles.end(), std::greater<double>());
  std::vector<Complex> poles;
  for (const ExtractedMode& mode : r->modes) poles.push_back(mode.eigenvalue);
  r->functions = Lsfd(frf, r->lines, poles, o.weigh_by_sigma, r->real_poles);
  r->refinement.status = Status::Failed(o.refine ? "no physical poles" : "not asked for");
  if (o.refine && !r->modes.empty()) {
    Refine(frf, o.weigh_by_sigma, r);
    AddMissedPoles(frf, o, r);
    DropInsignificantPoles(frf, o, r);
  }
  AddResidues(frf, r->functions, &r->modes);
  r->status = Status::Success(std::to_string(r->modes.size()) + " physical poles" +
                              (r->refinement.status.ok() ? ", refined" : ""));
}

}  // namespace ringid
