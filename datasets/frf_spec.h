// An FRF test's layout for `simulate --frf` (ringid-frf-spec/1,
// docs/inputs.md, docs/conventions.md §9): the inputs and outputs of
// contract §9's frf block, its frequency lines, the functions measured and
// their noise; the values are the model's, measured by Simulate
// (datasets/synthetic.h).
#ifndef RINGID_DATASETS_FRF_SPEC_H_
#define RINGID_DATASETS_FRF_SPEC_H_

#include <optional>
#include <string>
#include <vector>

#include "datasets/frf.h"

namespace ringid {

inline constexpr char kFrfSpecFormat[] = "ringid-frf-spec/1";

// Lines from `from` to `to` Hz (inclusive) every `step` Hz (EvenLines).
struct FrfLineRangeFields {
  double from = 0;
  double to = 0;
  double step = 0;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("from", &from);
    a->Visit("to", &to);
    a->Visit("step", &step);
  }
};

// A function measured: an output's response to an input, by their names.
struct FrfPairFields {
  std::string output, input;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("output", &output);
    a->Visit("input", &input);
  }
};

// The file, field by field: the lines as frequencies_hz or lines_hz (one of
// the two); without functions, every output with every input (output by
// output); without noise, simulate's default (SimulateOptions::frf_noise).
struct FrfSpecFields {
  std::optional<std::string> description;
  std::vector<FrfInputFields> inputs;
  std::vector<FrfOutputFields> outputs;
  std::optional<std::vector<double>> frequencies_hz;
  std::optional<FrfLineRangeFields> lines_hz;
  std::optional<std::vector<FrfPairFields>> functions;
  std::optional<double> noise;  // relative sd of re and of im per line (FrfSigma)

  template <class Archive>
  void Serialize(Archive* a) {
    a->Derived("format", std::string(kFrfSpecFormat));
    a->VisitIfSet("description", &description);
    a->Visit("inputs", &inputs);
    a->Visit("outputs", &outputs);
    a->VisitIfSet("frequencies_hz", &frequencies_hz);
    a->VisitIfSet("lines_hz", &lines_hz);
    a->VisitIfSet("functions", &functions);
    a->VisitIfSet("noise", &noise);
  }
};

struct FrfSpec {
  std::string path;  // for messages
  // The frf block the spec lays out, every value 0 and every sigma 1 until
  // Simulate measures them; checked by ReadFrf at standstill.
  FrfFields layout;
  std::optional<double> noise;
};

// The lines from `from` to `to` every `step` (each > 0, to >= from), as
// from + k step; a last line within 1e-9 steps of `to` is kept.
std::vector<double> EvenLines(double from, double to, double step);

// Reads and checks a spec: every rule of contract §9's frf block through
// ReadFrf, errors naming the spec's own field. False with `error`.
bool LoadFrfSpec(const std::string& path, FrfSpec* spec, LoadError* error);
bool ParseFrfSpec(const std::string& text, const std::string& path, FrfSpec* spec,
                  LoadError* error);

// The spec's frf block in a condition at `speed_m_s`: false with `error`
// naming the spec's field where §9 refuses it at that speed (a point force
// or sensor on the turning tread).
bool FrfOfSpec(const FrfSpec& spec, double speed_m_s, Frf* frf, LoadError* error);

}  // namespace ringid

#endif  // RINGID_DATASETS_FRF_SPEC_H_
