// The page of `ringid predict`: the modes of a parameter set, tables only.
#include "apps/html/pages.h"

namespace ringid::html {

void PredictPage(const json& report, Page* page) {
  page->Summary(FactsOf(
      report, {{"ok", "solved"}, {"error"}, {"overdamped", "overdamped (no oscillating mode)"}}));
  page->Heading("Modes");
  page->Table(
      {"mode", "plane", "frequency (Hz)", "damping ratio", "energy share of the label's element"},
      RowsOf(List(report, "modes"), [](const json& m) -> Row {
        return {ValueCell(Get(m, "label")), ValueCell(Get(m, "plane")),
                NumberCell(Num(m, "model_hz"), "%.3f"), NumberCell(Num(m, "damping_ratio")),
                NumberCell(Num(m, "label_energy_share"), "%.3f")};
      }));
}

}  // namespace ringid::html
