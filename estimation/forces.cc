#include "estimation/forces.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include <Eigen/Dense>

#include "model/campbell.h"

namespace ringid {
namespace {

using Clock = std::chrono::steady_clock;

// The measured channels of one order, weighted: A = W^1/2 H, y~ = W^1/2 y.
struct Weighted {
  Eigen::MatrixXcd A;  // channels x forces
  Eigen::VectorXcd y;
};

Weighted Weigh(const OrderResponse& order, const AxleResponseMatrix& H) {
  Weighted w{Eigen::MatrixXcd(order.channels.size(), kNumLugForces),
             Eigen::VectorXcd(order.channels.size())};
  int row = 0;
  for (const auto& [channel, phasor] : order.channels) {
    w.A.row(row) = H.row(static_cast<int>(channel)) / phasor.sigma;
    w.y(row) = phasor.value / phasor.sigma;
    ++row;
  }
  return w;
}

Eigen::MatrixXcd Columns(const Eigen::MatrixXcd& A, const std::vector<LugForce>& forces) {
  Eigen::MatrixXcd out(A.rows(), forces.size());
  for (size_t k = 0; k < forces.size(); ++k) out.col(k) = A.col(static_cast<int>(forces[k]));
  return out;
}

// Infinite where A has fewer rows than columns: its columns are dependent.
double ConditionNumber(const Eigen::MatrixXcd& A) {
  if (A.rows() < A.cols()) return INFINITY;
  const Eigen::JacobiSVD<Eigen::MatrixXcd> svd(A);
  const auto& s = svd.singularValues();
  return s.size() && s(s.size() - 1) > 0 ? s(0) / s(s.size() - 1) : INFINITY;
}

// The forces the weighted matrix determines, strongest first, each kept
// while the matrix of those kept has a condition number below the limit;
// the others into `undetermined` with why.
std::vector<LugForce> Determined(const Eigen::MatrixXcd& A, double limit,
                                 std::map<LugForce, UndeterminedForce>* undetermined) {
  std::vector<LugForce> order = {LugForce::kFx, LugForce::kFz, LugForce::kFy};
  std::sort(order.begin(), order.end(), [&](LugForce a, LugForce b) {
    return A.col(static_cast<int>(a)).norm() > A.col(static_cast<int>(b)).norm();
  });
  const double strongest = A.col(static_cast<int>(order[0])).norm();
  std::vector<LugForce> kept;
  char why[300];
  for (LugForce f : order) {
    const double norm = A.col(static_cast<int>(f)).norm();
    if (!(norm > strongest / limit)) {
      std::snprintf(why, sizeof why,
                    "no measured channel responds to it (its weighted response below 1/%.3g of "
                    "the strongest force's)",
                    limit);
      (*undetermined)[f] = {why, std::nullopt};
      continue;
    }
    std::vector<LugForce> with = kept;
    with.push_back(f);
    const double condition = ConditionNumber(Columns(A, with));
    if (!(condition <= limit)) {
      char number[80];
      if (std::isfinite(condition)) {
        std::snprintf(number, sizeof number, "%.3g, above %.3g", condition, limit);
      } else {
        std::snprintf(number, sizeof number, "infinite: %zu forces from %d channel%s",
                      with.size(), static_cast<int>(A.rows()), A.rows() == 1 ? "" : "s");
      }
      std::snprintf(why, sizeof why,
                    "the measured channels cannot tell it from the forces kept (condition "
                    "number with it %s); the estimates of those hold its share as if it were "
                    "zero",
                    number);
      (*undetermined)[f] = {why, condition};
      continue;
    }
    kept.push_back(f);
  }
  std::sort(kept.begin(), kept.end());
  return kept;
}

// Weighted least squares: x = (A^H A)^-1 A^H y.
Eigen::VectorXcd Solve(const Eigen::MatrixXcd& A, const Eigen::VectorXcd& y) {
  return A.colPivHouseholderQr().solve(y);
}

// The response matrix of condition c at order k under parameters p.
bool ResponseAt(const RigidRingModel& model, const Parameters& p, const ResponseCondition& c,
                double frequency_hz, AxleResponseMatrix* H, std::string* why) {
  return AxleResponse(model, p, c.speed_m_s, frequency_hz, H, why);
}

// p in condition c with coordinate i of `fp` moved by `step` in its
// coordinate (estimation/setup.h: log(value) for a positive parameter,
// value / TypicalScale otherwise); unmoved where the coordinate is another
// condition's or c's known value overrides it.
Parameters Moved(const ForceParameters& fp, const Parameters& p, const ResponseCondition& c,
                 int i, double step) {
  const ForceParameters::Coordinate& k = fp.coordinates[i];
  Parameters q = p;
  if (!k.key.condition.empty() && k.key.condition != c.name) return q;
  if (c.known.count(k.key.param)) return q;
  const bool log = Info(k.key.param).domain == Domain::kPositive;
  const double v = log ? p[k.key.param] * std::exp(step)
                       : p[k.key.param] + step * TypicalScale(k.key.param);
  q[k.key.param] = v;
  for (Param t : k.tied) {
    if (!c.known.count(t)) q[t] = v;
  }
  return q;
}

// The lug frequency of condition c under p: measured, or order 1's.
double LugHz(const ResponseCondition& c, int lugs, const Parameters& p) {
  return c.f_lug_hz.value_or(LugOrderHz(1, lugs, p[Param::r_e0], c.speed_m_s));
}

}  // namespace

bool ForcesOptions::IsValid(std::string* why) const {
  if (!(max_condition_number > 1) || !std::isfinite(max_condition_number)) {
    *why = "max_condition_number must be above 1";
    return false;
  }
  if (!(step_in_std > 0 && step_in_std < 1)) {
    *why = "step_in_std must lie in (0, 1)";
    return false;
  }
  return true;
}

ForceParameters ForceParameters::From(const IdentifyResult& fit) {
  ForceParameters fp;
  for (const ParameterEstimate& e : fit.estimates) {
    if (e.key.condition.empty()) {
      fp.shared[e.key.param] = e.value;
    } else {
      fp.by_condition[e.key.condition][e.key.param] = e.value;
    }
  }
  for (auto& [name, values] : fp.by_condition) {
    Parameters all = fp.shared;
    for (int i = 0; i < kNumParams; ++i) {
      if (values.IsSet(ParamAt(i))) all[ParamAt(i)] = values[ParamAt(i)];
    }
    values = all;
  }
  fp.source = "parameter values of an identify report";
  const Uncertainty& u = fit.uncertainty;
  const int n = static_cast<int>(fit.coordinate_names.size());
  if (!u.covariance_ok || u.covariance.rows() != n || u.covariance.cols() != n ||
      !u.covariance.allFinite() || !u.covariance.isApprox(u.covariance.transpose())) {
    return fp;  // none, or not one this can use: the values alone
  }
  for (const std::string& name : fit.coordinate_names) {
    Coordinate c;
    if (!ParameterKey::Parse(name, &c.key)) {  // not a fit of this catalogue: values only
      fp.coordinates.clear();
      return fp;
    }
    for (const ParameterEstimate& e : fit.estimates) {
      if (e.tied_to == c.key.param) c.tied.push_back(e.key.param);
    }
    fp.coordinates.push_back(c);
  }
  fp.covariance = u.covariance;
  fp.source = "identify report, with the covariance of its " +
              std::to_string(fp.coordinates.size()) + " coordinates";
  return fp;
}

Parameters ForceParameters::In(const ResponseCondition& c) const {
  const auto fit = by_condition.find(c.name);
  Parameters p = fit == by_condition.end() ? shared : fit->second;
  for (const auto& [q, v] : c.known) p[q] = v;
  return p;
}

void EstimateForces(const RigidRingModel& model, const ForceParameters& fp,
                    const ResponseDataset& data, const ForcesOptions& o, ForcesResult* r) {
  const auto start = Clock::now();
  *r = ForcesResult{};
  r->lugs_per_revolution = data.lugs_per_revolution;
  r->parameters = fp.source;
  r->max_condition_number = o.max_condition_number;
  std::string why;
  if (!o.IsValid(&why)) {
    r->status = Status::InvalidInput(why);
    return;
  }
  const int n = static_cast<int>(fp.coordinates.size());
  if (n > 0 && (fp.covariance.rows() != n || fp.covariance.cols() != n ||
                !fp.covariance.allFinite())) {
    r->status = Status::InvalidInput("the parameters' covariance is not " + std::to_string(n) +
                                     " x " + std::to_string(n) + " and finite, one row and "
                                     "column per coordinate");
    return;
  }
  for (const ResponseCondition& c : data.conditions) {
    const Parameters p = fp.In(c);
    for (Param q : model.parameters()) {
      if (!std::isfinite(p[q])) {
        r->status = Status::InvalidInput(std::string("parameter ") + ParamName(q) +
                                         " has no value in condition " + c.name);
        return;
      }
    }
    ConditionForces cf;
    cf.name = c.name;
    cf.speed_m_s = c.speed_m_s;
    cf.f_lug_measured = c.f_lug_hz.has_value();
    cf.f_lug_hz = LugHz(c, data.lugs_per_revolution, p);
    cf.model_valid_below_hz = ModelValidBelowHz(model, p);
    for (const OrderResponse& order : c.orders) {
      OrderForces of;
      of.order = order.order;
      of.frequency_hz = order.order * cf.f_lug_hz;
      of.above_model_range = !(of.frequency_hz < cf.model_valid_below_hz);
      for (const auto& [channel, phasor] : order.channels) of.channels.push_back(channel);
      AxleResponseMatrix H;
      const bool responds = ResponseAt(model, p, c, of.frequency_hz, &H, &why);
      const Weighted w = responds ? Weigh(order, H) : Weighted{};
      if (!responds || !w.A.allFinite() || !w.y.allFinite()) {  // one order: the others go on
        const std::string reason = responds ? "the weighted response is not finite (a sigma far "
                                              "below the amplitudes?)"
                                            : "the model's response: " + why;
        for (LugForce f : {LugForce::kFx, LugForce::kFz, LugForce::kFy}) of.undetermined[f] = {reason, std::nullopt};
        cf.orders.push_back(of);
        continue;
      }
      const std::vector<LugForce> kept =
          Determined(w.A, o.max_condition_number, &of.undetermined);
      if (kept.empty()) {
        cf.orders.push_back(of);
        continue;
      }
      const Eigen::MatrixXcd A = Columns(w.A, kept);
      const Eigen::VectorXcd x = Solve(A, w.y);
      of.condition_number = ConditionNumber(A);
      const Eigen::MatrixXcd covariance = (A.adjoint() * A).inverse();  // of re and im each
      const int over = static_cast<int>(A.rows() - A.cols());
      of.degrees_of_freedom = 2 * over;
      if (over > 0) of.chi_square = (w.y - A * x).squaredNorm();
      // The parameters' share: d x / d coordinate by central differences.
      Eigen::MatrixXcd G = Eigen::MatrixXcd::Zero(kept.size(), n);
      for (int i = 0; i < n; ++i) {
        const double sd = std::sqrt(std::max(fp.covariance(i, i), 0.0));
        if (!(sd > 0)) continue;
        const double h = o.step_in_std * sd;
        Eigen::VectorXcd side[2];
        for (int s = 0; s < 2; ++s) {
          AxleResponseMatrix Hs;
          const Parameters moved = Moved(fp, p, c, i, s ? -h : h);
          // The lug frequency moves with r_e0 where the dataset does not give it.
          const double hz = order.order * LugHz(c, data.lugs_per_revolution, moved);
          if (!ResponseAt(model, moved, c, hz, &Hs, &why)) {
            r->status = Status::Failed("condition " + c.name + ": the response near the "
                                       "parameters: " + why);
            return;
          }
          const Eigen::MatrixXcd As = Columns(Weigh(order, Hs).A, kept);
          if (!As.allFinite()) {
            r->status = Status::Failed("condition " + c.name + ": the response near the "
                                       "parameters is not finite");
            return;
          }
          side[s] = Solve(As, w.y);
        }
        G.col(i) = (side[0] - side[1]) / (2 * h);
      }
      for (size_t k = 0; k < kept.size(); ++k) {
        ForceEstimate e;
        e.value = x(k);
        e.std_measurement = std::sqrt(covariance(k, k).real());
        double parameters = 0;
        if (n > 0) {
          const Eigen::VectorXd re = G.row(k).real().transpose(), im = G.row(k).imag().transpose();
          parameters = (re.dot(fp.covariance * re) + im.dot(fp.covariance * im)) / 2;
        }
        e.std_total = std::sqrt(e.std_measurement * e.std_measurement + parameters);
        of.forces[kept[k]] = e;
      }
      cf.orders.push_back(of);
    }
    r->conditions.push_back(cf);
  }
  r->status = Status::Success();
  r->seconds = std::chrono::duration<double>(Clock::now() - start).count();
}

std::string ForcesResult::FullReport() const {
  std::ostringstream o;
  char line[400];
  o << "lug forces (" << lugs_per_revolution << " lugs per revolution; parameters: " << parameters
    << ")\n";
  for (const ConditionForces& c : conditions) {
    std::snprintf(line, sizeof line, "%s at %g m/s, f_lug %.4g Hz (%s); the model holds below %.4g Hz\n",
                  c.name.c_str(), c.speed_m_s, c.f_lug_hz,
                  c.f_lug_measured ? "measured" : "lugs V / (2 pi r_e0)", c.model_valid_below_hz);
    o << line;
    o << "  order      Hz  force        |F| N   phase deg   std meas.   std total\n";
    std::string above;  // the orders above the model's range
    for (const OrderForces& of : c.orders) {
      const char* mark = of.above_model_range ? "*" : " ";
      if (of.above_model_range) above += (above.empty() ? "" : ", ") + std::to_string(of.order);
      for (const auto& [force, e] : of.forces) {
        std::snprintf(line, sizeof line, "  %5d %7.2f%s %-5s %12.4g %11.1f %11.3g %11.3g\n",
                      of.order, of.frequency_hz, mark, ToString(force), std::abs(e.value),
                      std::arg(e.value) * 180 / M_PI, e.std_measurement, e.std_total);
        o << line;
      }
      for (const auto& [force, u] : of.undetermined) {
        std::snprintf(line, sizeof line, "  %5d %7.2f%s %-5s not determined: %s\n", of.order,
                      of.frequency_hz, mark, ToString(force), u.why.c_str());
        o << line;
      }
      if (of.chi_square) {
        std::snprintf(line, sizeof line, "  %5d          chi-square %.3g on %d degrees of freedom\n",
                      of.order, *of.chi_square, of.degrees_of_freedom);
        o << line;
      }
    }
    if (!above.empty()) {
      o << "  * order" << (above.find(',') == std::string::npos ? " " : "s ") << above
        << ": above the model's range, estimated with a rigid ring that does not describe the "
           "tire there (docs/forces.md §3)\n";
    }
  }
  if (!status.ok()) o << "status: " << ToString(status.outcome) << ": " << status.message << "\n";
  return o.str();
}

}  // namespace ringid
