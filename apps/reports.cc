#include "apps/reports.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include <unistd.h>

namespace ringid {
namespace {

using nlohmann::json;

json Finite(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json Matrix(const Eigen::MatrixXd& m) {
  json rows = json::array();
  for (int i = 0; i < m.rows(); ++i) {
    json row = json::array();
    for (int j = 0; j < m.cols(); ++j) row.push_back(Finite(m(i, j)));
    rows.push_back(row);
  }
  return rows;
}

json ShapeJson(const ShapeVector& shape) {
  json o = json::object();
  for (int i = 0; i < kNumDofs; ++i) {
    if (shape[i] == std::complex<double>(0, 0)) continue;
    o[DofName(static_cast<Dof>(i))] = {{"re", shape[i].real()},
                                       {"im", shape[i].imag()}};
  }
  return o;
}

}  // namespace

json IdentifyReport(const IdentifySummary& s, const Dataset& d,
                    const IdentifyOptions& o) {
  json r;
  r["report"] = "identify";
  r["dataset"] = d.name;
  r["method"] = MethodName(s.method);
  r["success"] = s.success;
  r["converged"] = s.converged;
  r["message"] = s.message;
  r["cost"] = Finite(s.cost);
  r["evaluations"] = s.evaluations;
  r["seconds"] = s.seconds;
  r["starts"] = s.starts;
  json costs = json::array();
  for (double c : s.start_costs) costs.push_back(Finite(c));
  r["start_costs"] = costs;
  r["frequency_weighting"] =
      o.residuals.frequency_weighting == FrequencyWeighting::kSigma ? "sigma"
                                                                     : "relative";
  r["relative_error"] = {{"in_plane_eq19", Finite(s.relative_error_in_plane)},
                         {"out_of_plane_eq20", Finite(s.relative_error_out_of_plane)}};
  json params = json::object();
  for (const ParameterEstimate& e : s.estimates) {
    json p;
    p["value"] = e.value;
    p["unit"] = Info(e.param).unit;
    p["free"] = e.free;
    if (e.tied_to) p["tied_to"] = ParamName(*e.tied_to);
    p["std"] = e.std ? json(*e.std) : json(nullptr);
    p["identifiable"] = IdentifiabilityName(e.identifiable);
    p["reason"] = e.reason;
    params[ParamName(e.param)] = p;
  }
  r["parameters"] = params;
  const Uncertainty& u = s.uncertainty;
  json cov;
  cov["names"] = s.coordinate_names;
  cov["coordinates"] = "log for positive parameters";
  cov["rank"] = u.rank;
  cov["computed"] = u.covariance_ok;
  if (!u.covariance_ok) cov["error"] = u.ok ? u.covariance_error : u.error;
  cov["matrix"] = u.covariance_ok ? Matrix(u.covariance) : json(nullptr);
  json sv = json::array();
  for (int i = 0; i < u.singular_values.size(); ++i) {
    sv.push_back(u.singular_values[i]);
  }
  cov["singular_values"] = sv;
  cov["condition_number"] = Finite(u.condition_number);
  r["covariance"] = cov;
  json modes = json::array();
  for (const ModeFit& m : s.modes) {
    json j;
    j["label"] = LabelName(m.label);
    j["measured_hz"] = m.measured_hz;
    j["measured_sigma_hz"] = m.measured_sigma_hz;
    j["model_hz"] = m.model_hz;
    j["model_label"] = LabelName(m.model_label);
    j["model_damping_ratio"] = m.model_damping;
    if (m.measured_damping) j["measured_damping_ratio"] = *m.measured_damping;
    if (m.mac) j["mac"] = *m.mac;
    for (const auto& [label, mac] : m.mac_all) j["mac_all"][LabelName(label)] = mac;
    modes.push_back(j);
  }
  r["modes"] = modes;
  return r;
}

json DiagnoseJson(const DiagnosisReport& r, const Dataset& d) {
  json j;
  j["report"] = "diagnose";
  j["dataset"] = d.name;
  j["success"] = r.success;
  if (!r.success) {
    j["message"] = r.message;
    return j;
  }
  j["gap_before"] = {{"chi2", r.chi2_before}, {"dof", r.dof},
                     {"p_value", r.p_value ? json(*r.p_value) : json(nullptr)},
                     {"significant", r.significant}, {"excess", r.gap_before}};
  auto misfits = [](const std::vector<ModeMisfit>& list, const std::vector<double>& shrink) {
    json where = json::array();
    for (size_t i = 0; i < list.size(); ++i) {
      const ModeMisfit& w = list[i];
      json q = {{"label", LabelName(w.label)}, {"chi2", w.chi2},
                {"frequency_sigma", w.frequency_sigma},
                {"damping_sigma", w.damping_sigma ? json(*w.damping_sigma) : json(nullptr)},
                {"shape_chi2", w.shape_chi2}};
      if (!w.worst_component.empty()) {
        q["worst_component"] = {{"dof", w.worst_component}, {"sigma", w.worst_component_sigma}};
      }
      if (i < shrink.size()) q["shrink"] = shrink[i];
      where.push_back(q);
    }
    return where;
  };
  const json where = misfits(r.where, r.mode_shrink);
  j["where"] = where;
  j["absorbed"] = r.absorbed;
  json ranking = json::array();
  for (const EffectFit& f : r.ranking) {
    json q = {{"effect", f.effect}, {"fitted", f.ok}};
    if (!f.ok) {
      q["note"] = f.note;
    } else {
      q["gap_after"] = f.gap_after;
      q["shrink"] = f.shrink;
      q["supported"] = f.supported;
      q["values"] = f.values;
      q["minimal_detectable"] = f.minimal_detectable;
      q["evidence"] = {{"chi2", f.chi2}, {"likelihood_ratio", f.lrt_statistic},
                       {"extra_parameters", f.extra_parameters}, {"lrt_p_value", f.lrt_p},
                       {"aic", f.aic}, {"bic", f.bic},
                       {"held_out_chi2", f.held_out_chi2 ? json(*f.held_out_chi2) : json(nullptr)},
                       {"mode_chi2", f.mode_chi2}};
    }
    ranking.push_back(q);
  }
  j["ranking"] = ranking;
  j["held_out_before"] = r.held_out_before ? json(*r.held_out_before) : json(nullptr);
  j["verdict"] = {{"effect", r.verdict}, {"indistinguishable", r.indistinguishable},
                  {"explanation", r.explanation}};
  for (const EffectFit& f : r.ranking) {  // the misfit once the verdict's effect is added
    if (f.effect == r.verdict) j["verdict"]["where_after"] = misfits(f.where, {});
  }
  j["seconds"] = r.seconds;
  return j;
}

json CompareJson(const ComparisonReport& r, const Dataset& d) {
  json j;
  j["report"] = "compare";
  j["dataset"] = d.name;
  j["success"] = r.success;
  if (!r.success) j["message"] = r.message;
  j["starts"] = r.starts;
  j["best_cost"] = Finite(r.best_cost);
  auto finite_list = [](const std::vector<double>& v) {
    json a = json::array();
    for (double x : v) a.push_back(Finite(x));
    return a;
  };
  for (const MethodRun& m : r.methods) {
    json q;
    q["starts"] = m.final_costs.size();
    q["success_rate"] = m.success_rate;
    q["final_costs"] = finite_list(m.final_costs);
    q["evaluations"] = m.evaluations;
    q["seconds"] = m.seconds;
    q["seconds_per_fit"] = m.seconds_per_fit;
    q["median_evaluations"] = m.median_evaluations;
    q["relative_error_in_plane_eq19"] = finite_list(m.relative_error_in_plane);
    q["relative_error_out_of_plane_eq20"] = finite_list(m.relative_error_out_of_plane);
    q["histories"] = json::array();  // per start: [[model solutions, cost], ...]
    for (const auto& h : m.histories) {
      json trace = json::array();
      for (const auto& [evaluations, cost] : h) trace.push_back({evaluations, Finite(cost)});
      q["histories"].push_back(trace);
    }
    j[MethodName(m.method)] = q;
  }
  j["initial"] = {{"cost", Finite(r.initial_cost)},
                  {"relative_error_in_plane_eq19", Finite(r.initial_error_in_plane)},
                  {"relative_error_out_of_plane_eq20", Finite(r.initial_error_out_of_plane)},
                  {"note", "the dataset's initial values; for the paper's Table 1 these are Table 2"}};
  j["paper_reported"] = {{"relative_error_in_plane_eq19", 1.41e-3},
                         {"relative_error_out_of_plane_eq20", 6.1e-3}};
  return j;
}

json IdentifiabilityJson(const IdentifiabilityReport& r, const Dataset& d) {
  json j;
  j["report"] = "identifiability";
  j["dataset"] = d.name;
  j["success"] = r.success;
  if (!r.success) j["message"] = r.message;
  j["rank"] = r.rank;
  j["num_residuals"] = r.num_residuals;
  j["condition_number"] = Finite(r.condition_number);
  j["rank_explanation"] = r.rank_explanation;
  json sv = json::array();
  for (int i = 0; i < r.singular_values.size(); ++i) sv.push_back(r.singular_values[i]);
  j["singular_values"] = sv;
  j["coordinates"] = r.coordinate_names;
  json params = json::object();
  for (const ParameterIdentifiability& p : r.parameters) {
    json q;
    q["value"] = p.value;
    q["identifiable"] = IdentifiabilityName(p.identifiable);
    q["reason"] = p.reason;
    q["std"] = p.std ? json(*p.std) : json(nullptr);
    q["wald_95"] = p.wald_95 ? json::array({p.wald_95->first, p.wald_95->second}) : json(nullptr);
    if (p.profile_95.computed) {
      q["profile_95"] = json::array({p.profile_95.lower ? json(*p.profile_95.lower) : json(nullptr),
                                     p.profile_95.upper ? json(*p.profile_95.upper) : json(nullptr)});
      q["profile_closed"] = p.profile_95.lower.has_value() && p.profile_95.upper.has_value();
      json curve = json::array();
      for (const auto& [v, d2] : p.profile_95.curve) curve.push_back({v, d2});
      q["profile_curve"] = curve;
    } else {
      q["profile_95"] = nullptr;
    }
    params[ParamName(p.param)] = q;
  }
  j["parameters"] = params;
  json combos = json::array();
  for (const Combination& c : r.combinations) {
    json terms = json::object();
    for (const auto& [name, coef] : c.terms) terms[name] = coef;
    combos.push_back({{"text", c.text}, {"meaning", c.meaning},
                      {"singular_value", c.singular_value}, {"terms", terms}});
  }
  j["combinations"] = combos;
  j["correlation"] = r.correlation.size() ? Matrix(r.correlation) : json(nullptr);
  json pairs = json::array();
  for (const CollinearSubset& c : r.collinear_pairs) {
    pairs.push_back({{"parameters", c.names}, {"collinearity_index", Finite(c.index)}});
  }
  j["collinear_pairs"] = pairs;
  j["identifiable_subset"] = r.identifiable_subset;
  json advice = json::array();
  for (const Advice& a : r.advice) {
    advice.push_back({{"parameter", a.parameter}, {"observation", a.observation},
                      {"information_gain", a.information_gain},
                      {"makes_identifiable", a.makes_identifiable}});
  }
  j["advice"] = advice;
  j["seconds"] = r.seconds;
  return j;
}

json PredictReport(const ModalSolution& s) {
  json r;
  r["report"] = "predict";
  r["ok"] = s.ok;
  if (!s.ok) r["error"] = s.error;
  json modes = json::array();
  for (const Mode& m : s.modes) {
    json j;
    j["label"] = LabelName(m.label);
    j["plane"] = PlaneName(m.plane());
    j["model_hz"] = m.frequency_hz;
    j["damping_ratio"] = m.damping_ratio;
    j["label_energy_share"] = m.energy[static_cast<int>(m.label)];
    j["shape"] = ShapeJson(m.shape);
    json paper = json::object();
    const RealShapeVector ps = m.PaperShape();
    for (int i = 0; i < kNumDofs; ++i) {
      if (m.shape[i] != std::complex<double>(0, 0)) {
        paper[DofName(static_cast<Dof>(i))] = ps[i];
      }
    }
    j["paper_eigenvector"] = paper;
    modes.push_back(j);
  }
  r["modes"] = modes;
  json gone = json::array();
  for (ModeLabel l : s.vanished) gone.push_back(LabelName(l));
  r["overdamped"] = gone;
  return r;
}

json ParameterSetJson(const IdentifySummary& s, const std::string& name,
                      const std::string& description) {
  json r;
  r["format"] = "ringid-parameters/1";
  r["name"] = name;
  r["description"] = description;
  json params = json::object();
  for (const ParameterEstimate& e : s.estimates) {
    params[ParamName(e.param)] = {
        {"value", e.value}, {"std", e.std ? json(*e.std) : json(nullptr)}};
  }
  r["parameters"] = params;
  return r;
}

bool CanWrite(const std::string& path, std::string* error) {
  const std::string probe = path + ".ringid-probe";
  std::FILE* f = std::fopen(probe.c_str(), "wb");
  if (!f) {
    *error = path + ": cannot write: " + std::strerror(errno);
    return false;
  }
  std::fclose(f);
  std::remove(probe.c_str());
  return true;
}

std::string JsonText(const nlohmann::json& report) {
  return report.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

bool WriteFileAtomically(const std::string& path, const std::string& text,
                         std::string* error) {
  return WriteFilesAtomically({{path, text}}, error);
}

bool WriteFilesAtomically(const std::vector<std::pair<std::string, std::string>>& files,
                          std::string* error) {
  for (size_t i = 0; i < files.size(); ++i) {
    for (size_t j = 0; j < i; ++j) {
      if (std::filesystem::path(files[i].first).lexically_normal() ==
          std::filesystem::path(files[j].first).lexically_normal()) {
        *error = files[i].first + ": named for two outputs";
        return false;
      }
    }
  }
  std::vector<std::string> tmps;
  auto fail = [&](const std::string& path) {
    *error = path + ": cannot write: " + std::strerror(errno);
    for (const std::string& t : tmps) std::remove(t.c_str());
    return false;
  };
  for (const auto& [path, text] : files) {
    tmps.push_back(path + ".tmp." + std::to_string(::getpid()));
    std::FILE* f = std::fopen(tmps.back().c_str(), "wb");
    if (!f) {
      tmps.pop_back();
      return fail(path);
    }
    const bool wrote = std::fwrite(text.data(), 1, text.size(), f) == text.size();
    if (std::fclose(f) != 0 || !wrote) return fail(path);
  }
  // Every file is complete before the first rename.
  for (size_t i = 0; i < files.size(); ++i) {
    if (std::rename(tmps[i].c_str(), files[i].first.c_str()) != 0) {
      tmps.erase(tmps.begin(), tmps.begin() + i);
      return fail(files[i].first);
    }
  }
  return true;
}

}  // namespace ringid
