// What `ringid poles` writes (operations/poles.h): POLES.json, the physical
// poles of a file's FRFs with their standard errors and residues, and its
// report (--report), with each condition's stabilisation diagram and each
// function against its synthesis as extract's (report/extract_report.h).
#ifndef RINGID_REPORT_POLES_REPORT_H_
#define RINGID_REPORT_POLES_REPORT_H_

#include <optional>
#include <string>
#include <vector>

#include "estimation/status.h"
#include "report/extract_report.h"
#include "report/report.h"

namespace ringid {

inline constexpr char kPolesFormat[] = "ringid-poles/1";

// A residue of one function: response and reference as the file names them
// (UFF: node and direction, "101:+3"), in the condition's units.
struct PoleResidue {
  std::string response, reference;
  double re = 0, im = 0;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("response", &response);
    a->Visit("reference", &reference);
    a->Visit("re", &re);
    a->Visit("im", &im);
  }
};

// One component of a pole's shape.
struct PoleShapeValue {
  std::string coordinate;
  double re = 0, im = 0;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("coordinate", &coordinate);
    a->Visit("re", &re);
    a->Visit("im", &im);
  }
};

// A physical pole (Im λ > 0), damped frequency (contract §2).
struct FoundPole {
  int condition = 0;  // into PolesFile::conditions
  double frequency_hz = 0, damping_ratio = 0;
  std::optional<double> frequency_sigma_hz, damping_sigma;  // where the refinement gives them
  int stable_orders = 0;
  std::vector<PoleResidue> residues;
  // Over the side with several coordinates: "responses", or "references"
  // (a roving hammer); its largest component real and positive.
  std::string shape_over;
  std::vector<PoleShapeValue> shape;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("condition", &condition);
    a->Visit("frequency_hz", &frequency_hz);
    a->Visit("frequency_sigma_hz", &frequency_sigma_hz);
    a->Visit("damping_ratio", &damping_ratio);
    a->Visit("damping_sigma", &damping_sigma);
    a->Visit("stable_orders", &stable_orders);
    a->Visit("residues", &residues);
    a->Visit("shape_over", &shape_over);
    a->Visit("shape", &shape);
  }
};

// One set of lines of the file.
struct PolesCondition {
  std::string name;
  int functions = 0, lines = 0;
  double low_hz = 0, high_hz = 0;  // the lines used
  std::string units;               // of the residues
  // "given" (coherence or the dataset's sigma) or "from the residuals".
  std::string noise;
  int max_order = 0;  // of pLSCF's diagram

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("name", &name);
    a->Visit("functions", &functions);
    a->Visit("lines", &lines);
    a->Visit("low_hz", &low_hz);
    a->Visit("high_hz", &high_hz);
    a->Visit("units", &units);
    a->Visit("noise", &noise);
    a->Visit("max_order", &max_order);
  }
};

struct PolesFile {
  std::string format = kPolesFormat;
  std::string source;
  std::vector<PolesCondition> conditions;
  std::vector<FoundPole> poles;  // by condition, ascending frequency
  std::vector<std::string> notes;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("format", &format);
    a->Visit("source", &source);
    a->Visit("conditions", &conditions);
    a->Visit("poles", &poles);
    a->Visit("notes", &notes);
  }
};

// The report: the same poles, and per condition the diagram and the
// synthesis (ExtractCondition, its `condition` the index above).
struct PolesBody {
  std::string dataset;  // the file, as poles was given it
  Status status;
  PolesFile poles;
  std::vector<ExtractCondition> conditions;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("dataset", &dataset);
    status.Serialize(a);
    a->Visit("poles", &poles);
    a->Visit("conditions", &conditions);
  }
};

using PolesReport = Report<ReportKind::kPoles, PolesBody>;

}  // namespace ringid

#endif  // RINGID_REPORT_POLES_REPORT_H_
