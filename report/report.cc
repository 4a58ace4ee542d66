#include "report/report.h"

#include <openssl/evp.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace ringid {

std::string FileSha256(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return "";
  std::ifstream in(path, std::ios::binary);
  if (!in) return "";
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int size = 0;
  if (!EVP_Digest(bytes.data(), bytes.size(), digest, &size, EVP_sha256(), nullptr)) return "";
  static const char kHex[] = "0123456789abcdef";
  std::string hex;
  for (unsigned int i = 0; i < size; ++i) {
    hex += kHex[digest[i] >> 4];
    hex += kHex[digest[i] & 15];
  }
  return hex;
}

Provenance MakeProvenance(int argc, const char* const* argv,
                          const std::vector<std::pair<std::string, std::string>>& role_paths,
                          std::optional<long> seed) {
  Provenance p;
  p.ringid_version = RINGID_VERSION;
  p.command_line.assign(argv, argv + argc);
  for (const auto& [role, path] : role_paths) {
    if (!path.empty()) p.inputs.push_back({role, path, FileSha256(path)});
  }
  p.seed = seed;
  return p;
}

bool ReportHeader(const Json& json, ReportKind* kind, std::string* error) {
  if (!json.is_object() || !json.contains("report")) {
    *error = "report: missing (not a ringid report)";
    return false;
  }
  if (!JsonReader::FromJson(json["report"], "report", kind, error)) return false;
  const auto version = json.find("schema_version");
  if (version == json.end() || !version->is_number_integer()) {
    *error = "schema_version: missing (a report of ringid before schema " +
             std::to_string(kReportSchemaVersion) + "; write it again with this ringid)";
    return false;
  }
  if (version->get<long>() != kReportSchemaVersion) {
    *error = "schema_version: " + std::to_string(version->get<long>()) + ", this ringid reads " +
             std::to_string(kReportSchemaVersion);
    return false;
  }
  return true;
}

std::string CampaignTable(const CampaignBody& c) {
  const bool identify = c.command == ReportKind::kIdentify;
  const auto number = [](const std::optional<double>& v, const char* format) {
    char text[48] = "-";
    if (v && std::isfinite(*v)) std::snprintf(text, sizeof text, format, *v);
    return std::string(text);
  };
  std::string table =
      identify ? "| dataset | status | cost | eq. (19) | eq. (20) | seconds |\n"
                 "| --- | --- | --- | --- | --- | --- |\n"
               : "| dataset | verdict | indistinguishable | gap before | gap after | shrink | seconds |\n"
                 "| --- | --- | --- | --- | --- | --- | --- |\n";
  for (const CampaignRow& r : c.datasets) {
    std::string status = r.status.ok() ? (r.converged.value_or(false) ? "converged" : "not converged")
                                       : std::string("failed: ") + r.status.message;
    table += "| " + r.dataset + " | ";
    if (identify) {
      table += status + " | " + number(r.cost, "%.4g") + " | " +
               number(r.relative_error_in_plane_eq19, "%.3e") + " | " +
               number(r.relative_error_out_of_plane_eq20, "%.3e");
    } else {
      std::string group;
      for (const Effect* g : r.indistinguishable.value_or(std::vector<const Effect*>{})) group += (group.empty() ? "" : "+") + std::string(EffectName(g));
      table += (r.status.ok() && r.verdict ? std::string(EffectName(*r.verdict)) : status) + " | " +
               group + " | " +
               number(r.gap_before, "%.4g") + " | " + number(r.gap_after, "%.4g") + " | " +
               number(r.shrink ? std::optional(100 * *r.shrink) : std::nullopt, "%.1f %%");
    }
    table += " | " + number(r.seconds, "%.3g") + " |\n";
  }
  if (!identify) table += std::string("\n") + kCampaignGapMeaning + "\n";
  return table;
}

PredictBody PredictBody::From(const ModalSolution& solution) {
  PredictBody b;
  b.status = solution.ok ? Status::Success() : Status::Failed(solution.error);
  for (const Mode& m : solution.modes) {
    PredictedMode p;
    p.label = m.label;
    p.model_hz = m.frequency_hz;
    p.damping_ratio = m.damping_ratio;
    p.label_energy_share = m.energy[static_cast<int>(m.label)];
    const RealShapeVector paper = m.PaperShape();
    for (int i = 0; i < kNumDofs; ++i) {
      if (m.shape[i] == std::complex<double>(0, 0)) continue;
      p.shape[static_cast<Dof>(i)] = m.shape[i];
      p.paper_eigenvector[static_cast<Dof>(i)] = paper[i];
    }
    b.modes.push_back(std::move(p));
  }
  b.overdamped = solution.vanished;
  return b;
}

std::vector<std::array<double, kLugColumns>> ShownAmplitudes(const LugExcitation& e) {
  std::vector<std::array<double, kLugColumns>> shown;
  std::array<double, kLugColumns> largest{};
  for (const LugOrderExcitation& k : e.orders) {
    std::array<double, kLugColumns> row;
    for (int c = 0; c < kLugColumns; ++c) {
      row[c] = std::abs(c < 3 ? k.force[c] : k.response[c - 3]);
      largest[c] = std::max(largest[c], row[c]);
    }
    shown.push_back(row);
  }
  for (auto& row : shown) {
    for (int c = 0; c < kLugColumns; ++c) row[c] = row[c] < 1e-9 * largest[c] ? 0.0 : row[c];
  }
  return shown;
}

std::array<double, 3> ShownMeans(const LugExcitation& e) {
  std::array<double, 3> mean = e.mean_force;
  const double top = std::max({std::abs(mean[0]), std::abs(mean[1]), std::abs(mean[2])});
  for (double& m : mean) m = std::abs(m) < 1e-9 * top ? 0.0 : m;
  return mean;
}

std::string PredictBody::FullReport() const {
  std::string text;
  char line[160];
  for (const std::string& note : parameter_notes.value_or(std::vector<std::string>{})) {
    text += kParameterNotePrefix + note + "\n";
  }
  if (parameter_notes && !parameter_notes->empty()) text += "\n";
  std::snprintf(line, sizeof line, "%-22s %-13s %10s %8s\n", "mode", "plane", "Hz", "zeta");
  text += line;
  for (const PredictedMode& m : modes) {
    std::snprintf(line, sizeof line, "%-22s %-13s %10.3f %8.4f\n", LabelName(m.label),
                  PlaneName(LabelPlane(m.label)), m.model_hz, m.damping_ratio);
    text += line;
  }
  for (ModeLabel l : overdamped) {
    std::snprintf(line, sizeof line, "%-22s overdamped: no oscillating mode\n", LabelName(l));
    text += line;
  }
  const auto table = [&](const std::vector<SpeedModes>& rows, const char* title, bool named) {
    text += title;
    std::snprintf(line, sizeof line, named ? "%-12s %8s" : "%8s", named ? "condition" : "m/s", "m/s");
    text += line;
    for (const PredictedMode& m : modes) {
      std::snprintf(line, sizeof line, " %10.10s", LabelName(m.label));
      text += line;
    }
    text += "\n";
    for (const SpeedModes& s : rows) {
      if (named) std::snprintf(line, sizeof line, "%-12.12s %8.3g", s.condition.value_or("").c_str(), s.speed_m_s);
      else std::snprintf(line, sizeof line, "%8.3g", s.speed_m_s);
      text += line;
      for (const PredictedMode& m : modes) {
        const auto it = s.modes.find(m.label);
        if (it == s.modes.end()) std::snprintf(line, sizeof line, " %10s", "-");
        else std::snprintf(line, sizeof line, " %10.2f", it->second.first);
        text += line;
      }
      text += "\n";
    }
  };
  if (conditions) table(*conditions, "\nmodes by condition (Hz):\n", true);
  if (speeds) table(*speeds, "\nmodes by speed (Hz):\n", false);
  if (critical_speeds) {
    std::snprintf(line, sizeof line,
                  "\ncritical speeds (%d lugs per revolution; orders 1 to %d, --max_order):\n",
                  lugs_per_revolution.value_or(0), max_order.value_or(0));
    text += line;
    if (critical_speeds->empty()) text += "  none within the speeds given\n";
    for (const CriticalSpeed& c : *critical_speeds) {
      std::snprintf(line, sizeof line, "  order %2d meets %-20s at %7.3f m/s, %8.2f Hz, zeta %.4f\n",
                    c.order, LabelName(c.label), c.speed_m_s, c.frequency_hz, c.damping_ratio);
      text += line;
    }
  }
  if (lug_excitation) {
    std::snprintf(line, sizeof line,
                  "\nlug excitation (amplitudes of orders 1 to %d, --max_order; forces N, axle "
                  "N and N m, rim rad/s):\n",
                  max_order.value_or(0));
    text += line;
    for (const LugExcitation& e : *lug_excitation) {
      const std::array<double, 3> mean = ShownMeans(e);
      std::snprintf(line, sizeof line, "at %g m/s, mean forces F_x %.4g, F_z %.4g, F_y %.4g N\n",
                    e.speed_m_s, mean[0], mean[1], mean[2]);
      text += line;
      text += "order       Hz      F_x      F_z      F_y";
      for (int c = 0; c < kNumTimeOutputs; ++c) {
        std::snprintf(line, sizeof line, " %13.13s", TimeOutputName(c));
        text += line;
      }
      text += "\n";
      const auto shown = ShownAmplitudes(e);
      for (size_t k = 0; k < e.orders.size(); ++k) {
        std::snprintf(line, sizeof line, "%5d %8.2f", e.orders[k].order, e.orders[k].frequency_hz);
        text += line;
        for (int c = 0; c < kLugColumns; ++c) {
          std::snprintf(line, sizeof line, c < 3 ? " %8.3g" : " %13.4g", shown[k][c]);
          text += line;
        }
        text += "\n";
      }
    }
  }
  return text;
}

}  // namespace ringid
