// The FRF spec of `simulate --frf`: its own fields here, every rule of the
// frf block by ReadFrf on the block it lays out (contract §9).
#include "datasets/frf_spec.h"

#include <cmath>
#include <string>

#include "datasets/dataset.h"
#include "datasets/load_failure.h"
#include "datasets/typed_file.h"

namespace ringid {
namespace {

using internal::Fail;
using internal::Captured;
using internal::Failure;

// A line takes at least 8 bytes of a dataset (its frequency, re, im and
// sigma, each a digit and a separator): more lines than this could not be
// read back.
constexpr double kMaxLines = kMaxFileBytes / 8.0;

std::vector<double> Lines(const FrfSpecFields& j) {
  if (j.frequencies_hz && j.lines_hz) {
    Fail("lines_hz", "not with frequencies_hz: the lines are given one way");
  }
  if (j.frequencies_hz) return *j.frequencies_hz;  // ReadFrf checks them
  if (!j.lines_hz) {
    Fail("frequencies_hz", "missing: give the lines as frequencies_hz [F1, F2, ...] or as "
                           "lines_hz {\"from\": F, \"to\": T, \"step\": S}");
  }
  const FrfLineRangeFields& r = *j.lines_hz;
  if (!(std::isfinite(r.from) && r.from > 0)) {
    Fail("lines_hz.from", "must be a positive number of Hz (contract §9: lines > 0)");
  }
  if (!(std::isfinite(r.step) && r.step > 0)) {
    Fail("lines_hz.step", "must be a positive number of Hz");
  }
  if (!(std::isfinite(r.to) && r.to >= r.from)) {
    Fail("lines_hz.to", "must be a number of Hz not below lines_hz.from");
  }
  if ((r.to - r.from) / r.step + 1 > kMaxLines) {
    Fail("lines_hz.step", "gives more than " + std::to_string(static_cast<long>(kMaxLines)) +
                              " lines, more than a dataset of at most " +
                              std::to_string(kMaxFileBytes) + " bytes holds");
  }
  const std::vector<double> lines = EvenLines(r.from, r.to, r.step);
  for (size_t i = 1; i < lines.size(); ++i) {
    if (!(lines[i] > lines[i - 1])) {
      Fail("lines_hz.step", "is too small beside lines_hz.from: the lines would not increase");
    }
  }
  return lines;
}

FrfFunctionFields Placeholder(const std::string& output, const std::string& input, size_t lines) {
  FrfFunctionFields f;
  f.output = output;
  f.input = input;
  f.re.assign(lines, 0.0);
  f.im.assign(lines, 0.0);
  f.sigma.emplace(lines, 1.0);
  return f;
}

// ReadFrf's fields under the prefix "" start with '.'.
void Unprefixed(LoadError* error) {
  if (!error->field.empty() && error->field[0] == '.') error->field.erase(0, 1);
}

bool Check(const FrfSpecFields& j, FrfSpec* spec, LoadError* error) {
  const bool read = Captured(error, [&] {
    FrfFields& layout = spec->layout;
    layout.inputs = j.inputs;
    layout.outputs = j.outputs;
    layout.frequencies_hz = Lines(j);
    const size_t lines = layout.frequencies_hz.size();
    if (j.functions) {
      for (const FrfPairFields& pair : *j.functions) {
        layout.functions.push_back(Placeholder(pair.output, pair.input, lines));
      }
    } else {
      for (const FrfOutputFields& out : j.outputs) {
        for (const FrfInputFields& in : j.inputs) {
          layout.functions.push_back(Placeholder(out.name, in.name, lines));
        }
      }
    }
    if (j.noise && !(std::isfinite(*j.noise) && *j.noise >= 0)) {
      Fail("noise", "must be a number >= 0 (the sd of re and of im per line, relative to |H|; "
                    "0: no noise)");
    }
    spec->noise = j.noise;
  });
  Frf standing;
  return read && FrfOfSpec(*spec, 0, &standing, error);
}

}  // namespace

std::vector<double> EvenLines(double from, double to, double step) {
  const long n = static_cast<long>(std::floor((to - from) / step + 1e-9)) + 1;
  std::vector<double> lines;
  for (long k = 0; k < n; ++k) lines.push_back(from + k * step);
  return lines;
}

bool ParseFrfSpec(const std::string& text, const std::string& path, FrfSpec* spec,
                  LoadError* error) {
  *spec = FrfSpec{};
  spec->path = path;
  return internal::ReadTyped<FrfSpecFields>(
      text, path, kFrfSpecFormat, error,
      [&](const FrfSpecFields& j) { return Check(j, spec, error); });
}

bool LoadFrfSpec(const std::string& path, FrfSpec* spec, LoadError* error) {
  std::string text;
  return ReadInputFile(path, &text, error) && ParseFrfSpec(text, path, spec, error);
}

bool FrfOfSpec(const FrfSpec& spec, double speed_m_s, Frf* frf, LoadError* error) {
  if (ReadFrf(spec.layout, speed_m_s, spec.path, "", frf, error)) return true;
  Unprefixed(error);
  return false;
}

}  // namespace ringid
