// The page of `ringid predict`: the modes of a parameter set, tables only.
#include "apps/html/pages.h"

namespace ringid::html {

void PredictPage(const PredictReport& report, Page* page) {
  const PredictBody& r = report.body;
  std::vector<std::string> overdamped;
  for (ModeLabel label : r.overdamped) overdamped.push_back(ToString(label));
  page->Summary({{"status", NameCell(r.status.outcome)},
                 {"message", TextCell(r.status.message)},
                 {"overdamped (no oscillating mode)", ListCell(overdamped)}});
  std::vector<Row> rows;
  for (const PredictedMode& m : r.modes) {
    rows.push_back({NameCell(m.label), NameCell(LabelPlane(m.label)), NumberCell(m.model_hz, "%.3f"),
                    NumberCell(m.damping_ratio), NumberCell(m.label_energy_share, "%.3f")});
  }
  page->TableSection(
      "Modes",
      {"mode", "plane", "frequency (Hz)", "damping ratio", "energy share of the label's element"},
      rows);
}

void ProvenanceSection(const Provenance& p, Page* page) {
  std::string command;
  for (const std::string& arg : p.command_line) command += (command.empty() ? "" : " ") + arg;
  page->Heading("Provenance");
  page->Facts({{"ringid version", TextCell(p.ringid_version)},
               {"command line", TextCell(command)},
               {"seed", NumberCell(p.seed ? std::optional<double>(*p.seed) : std::nullopt, "%.0f")},
               {"derivatives", TextCell(ToString(p.derivatives))}});
  std::vector<Row> rows;
  for (const InputFile& f : p.inputs) {
    rows.push_back({TextCell(f.role), TextCell(f.path), TextCell(f.sha256.empty() ? "–" : f.sha256)});
  }
  page->Table({"input", "path", "SHA-256"}, rows);
}

}  // namespace ringid::html
