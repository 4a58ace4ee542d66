#include "tests/test_support.h"

#include <sys/stat.h>
#include <sys/wait.h>
#include <spawn.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "datasets/synthetic.h"

namespace ringid::testing {

std::string SourcePath(const std::string& relative) {
  return std::string(RINGID_SOURCE_DIR) + "/" + relative;
}

std::string CorpusDir() {
  const char* dir = std::getenv("RINGID_CORPUS_DIR");
  return dir && *dir ? std::string(dir) : SourcePath("../shared/data");
}

std::string CorpusPath(const std::string& relative) { return CorpusDir() + "/" + relative; }

std::string DatasetErrorOf(const nlohmann::json& j, const std::string& file) {
  Dataset d;
  LoadError e;
  if (ParseDataset(j.dump(), file, &d, &e)) return "";
  return e.OneLine();
}

UffFile ParsedUff(const std::string& text) {
  UffFile f;
  LoadError e;
  EXPECT_TRUE(ParseUff(text, "test.uff", &f, &e)) << e.OneLine();
  return f;
}

UffMap ParsedUffMap(const std::string& json) {
  UffMap map;
  LoadError e;
  EXPECT_TRUE(ParseUffMap(json, "map.json", &map, &e)) << e.OneLine();
  return map;
}

void CorpusTest::SetUp() {
  struct stat st;
  if (stat(CorpusDir().c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) {
    GTEST_SKIP() << "the public corpus directory " << CorpusDir()
                 << " is absent (set RINGID_CORPUS_DIR to read it elsewhere)";
  }
}

Parameters Table2() {
  Parameters p;
  using P = Param;
  p[P::c_bx] = p[P::c_bz] = 1.38e3;
  p[P::c_btheta] = 1.85e1;
  p[P::k_bx] = p[P::k_bz] = 3.84e5;
  p[P::k_btheta] = 7.67e3;
  p[P::K_cx] = 1.03e4;
  p[P::sigma_cx] = 6.73e-2;
  p[P::r_e0] = 3.19e-1;
  p[P::k_cz] = 3.04e5;
  p[P::c_by] = 1.21e3;
  p[P::c_bgamma] = p[P::c_bpsi] = 6.06;
  p[P::k_by] = 2.81e5;
  p[P::k_bgamma] = p[P::k_bpsi] = 1.41e3;
  p[P::K_cy] = 6.37e2;
  p[P::sigma_cy] = 1.17e-3;
  p[P::r_l0] = 2.58e-3;
  p[P::t_0] = 1.35e-3;
  return p;
}

Parameters WithEffectSized(const Effect& effect, Parameters p) {
  for (Param q : effect.parameters()) {
    switch (q) {
      case Param::m_a: p[q] = 15; break;
      case Param::dk_bz: p[q] = 0.2 * p[Param::k_bz]; break;
      case Param::dk_bpsi: p[q] = 0.2 * p[Param::k_bpsi]; break;
      case Param::s_h: p[q] = 0.5 / p[Param::k_bz]; break;
      case Param::k_cpsi: p[q] = 0.2 * p[Param::k_bpsi]; break;
      case Param::k_atheta: p[q] = p[Param::k_btheta]; break;
      case Param::dm: p[q] = 1; break;
      case Param::k_xy: p[q] = 0.3 * std::sqrt(p[Param::k_bx] * p[Param::k_by]); break;
      default: ADD_FAILURE() << "no size for " << ParamName(q) << " of " << effect.name();
    }
  }
  return p;
}

Parameters PaperIdentified() {
  Parameters shipped;
  LoadError error;
  EXPECT_TRUE(LoadParameterSet(SourcePath("datasets/paper/parameters.json"),
                               &shipped, &error))
      << error.OneLine();
  Parameters p = Table2();
  for (Param q : {Param::m_b, Param::I_ay, Param::I_by, Param::I_bx,
                  Param::I_bz, Param::F_cz0}) {
    p[q] = shipped[q];
  }
  return p;
}

Dataset SyntheticDataset(const RigidRingModel& model, const Parameters& truth,
                         double freq_rel_sigma, double damping_rel_sigma,
                         double shape_sigma, std::mt19937_64* rng) {
  SimulateOptions o;
  o.frequency_noise = freq_rel_sigma;
  o.damping_noise = damping_rel_sigma;
  o.shape_noise = shape_sigma;
  o.hub_components = false;
  Dataset d;
  d.name = "synthetic";
  d.path = "synthetic";
  std::string why;
  EXPECT_TRUE(Simulate(model, truth, o, rng, &d, &why)) << why;
  return d;
}

namespace {

using nlohmann::json;

json ValidDataset() {
  return json::parse(R"({
    "format": "ringid-modal-dataset/1", "name": "t", "description": "d",
    "known": {"m_b": 2.37}, "initial": {"k_bx": 3e5}, "ties": {"k_bz": "k_bx"},
    "modes": [{"label": "vertical", "plane": "in_plane", "frequency_hz": 74.5,
               "frequency_sigma_hz": 0.5, "damping_ratio": 0.08,
               "damping_sigma": 0.02, "shape": {"z_b": 1.0, "x_b": 0.01},
               "shape_sigma": 0.05}]})");
}

// The JSON pointer of a dotted field such as "modes[0].shape.z_b".
json::json_pointer Pointer(const std::string& field) {
  std::string p;
  for (char c : field) {
    if (c == '.' || c == '[') p += '/';
    else if (c != ']') p += c;
  }
  return json::json_pointer("/" + p);
}

// Raw tokens that JSON values cannot hold, spliced into the text.
const char kRaw[] = "__RAW_TOKEN__";

}  // namespace

std::vector<MalformedDataset> MalformedDatasets() {
  std::vector<MalformedDataset> out;
  auto add = [&](const std::string& what, const json& j, const std::string& field,
                 const std::string& raw = "") {
    std::string text = j.dump(1);
    if (!raw.empty()) {
      const std::string quoted = std::string("\"") + kRaw + "\"";
      text.replace(text.find(quoted), quoted.size(), raw);
    }
    out.push_back({what, text, field});
  };
  enum Kind { kString, kPositive, kRatio, kNumber, kObject };
  const struct { const char* field; Kind kind; bool required; } fields[] = {
      {"format", kString, true},        {"name", kString, true},
      {"description", kString, false},  {"known", kObject, false},
      {"initial", kObject, false},      {"ties", kObject, false},
      {"known.m_b", kPositive, false},  {"initial.k_bx", kPositive, false},
      {"ties.k_bz", kString, false},    {"modes[0].label", kString, true},
      {"modes[0].plane", kString, false},
      {"modes[0].frequency_hz", kPositive, true},
      {"modes[0].frequency_sigma_hz", kPositive, false},
      {"modes[0].damping_ratio", kRatio, false},
      {"modes[0].damping_sigma", kPositive, false},
      {"modes[0].shape", kObject, false}, {"modes[0].shape.x_b", kNumber, false},
      {"modes[0].shape_sigma", kPositive, false}};
  const json wrong_types[] = {json("x"), json(3), json(true), json(nullptr),
                              json::array(), json::object()};
  for (const auto& f : fields) {
    const auto ptr = Pointer(f.field);
    if (f.required) {
      json j = ValidDataset();
      j[ptr.parent_pointer()].erase(ptr.back());
      add(std::string(f.field) + " missing", j, f.field);
    }
    for (const json& bad : wrong_types) {
      const bool fits = (f.kind == kString && bad.is_string()) ||
                        (f.kind == kObject && bad.is_object()) ||
                        (f.kind != kString && f.kind != kObject && bad.is_number());
      if (fits) continue;
      json j = ValidDataset();
      j[ptr] = bad;
      // An emptied optional object is valid; an emptied shape is not.
      if (bad.is_object() && f.kind == kObject && std::string(f.field) != "modes[0].shape") continue;
      add(std::string(f.field) + " = " + bad.dump(), j, f.field);
    }
    if (f.kind == kString) {
      json j = ValidDataset();
      j[ptr] = std::string(f.field) == "name" ? "" : "no-such-thing";
      if (std::string(f.field) != "description") {
        add(std::string(f.field) + " bad value", j, f.field);
      }
    }
    if (f.kind == kPositive || f.kind == kRatio || f.kind == kNumber) {
      for (const char* raw : {"NaN", "Infinity", "1e999", "-1e999"}) {
        json j = ValidDataset();
        j[ptr] = kRaw;
        add(std::string(f.field) + " = " + raw, j, f.field, raw);
      }
    }
    if (f.kind == kPositive || f.kind == kRatio) {
      for (double v : {0.0, -1.0}) {
        json j = ValidDataset();
        j[ptr] = v;
        add(std::string(f.field) + " = " + std::to_string(v), j, f.field);
      }
    }
    if (f.kind == kRatio) {
      json j = ValidDataset();
      j[ptr] = 1.0;
      add(std::string(f.field) + " = 1", j, f.field);
    }
  }
  // Values no rigid ring can have (docs/conventions.md §3): issue 21's typos
  // (the template's 36.1 Hz typed as 3610, 77.5 as 7750), and absurd sizes.
  const struct { const char* field; double value; } absurd[] = {
      {"modes[0].frequency_hz", 3610},   {"modes[0].frequency_hz", 7750},
      {"modes[0].frequency_hz", 1e30},   {"modes[0].frequency_hz", 0.5},
      {"initial.k_bx", 1e300},           {"initial.k_bx", 2e12},
      {"known.m_b", 1e13}};
  for (const auto& a : absurd) {
    json j = ValidDataset();
    j[Pointer(a.field)] = a.value;
    std::ostringstream what;
    what << a.field << " = " << a.value << " (outside physics)";
    add(what.str(), j, a.field);
  }
  // Unknown keys, names and ties.
  const struct { const char* what; const char* field; const char* at; } unknown[] = {
      {"unknown top-level key", "extra", ""},
      {"unknown parameter in known", "known.k_qq", "/known"},
      {"unknown parameter in initial", "initial.k_qq", "/initial"},
      {"unknown key in a mode", "modes[0].freq", "/modes/0"},
      {"unknown degree of freedom", "modes[0].shape.q_b", "/modes/0/shape"}};
  for (const auto& u : unknown) {
    json j = ValidDataset();
    const std::string field = u.field;
    j[json::json_pointer(u.at)][field.substr(field.rfind('.') + 1)] = 1.0;
    add(u.what, j, u.field);
  }
  json j = ValidDataset();
  j["modes"][0]["label"] = "hub_vertical";
  add("label outside the contract", j, "modes[0].label");
  j = ValidDataset();
  j["modes"].push_back(j["modes"][0]);
  add("label twice", j, "modes[1].label");
  j = ValidDataset();
  j["modes"] = json::array();
  add("no modes", j, "modes");
  j = ValidDataset();
  j["modes"][0].erase("damping_ratio");
  add("damping sigma without ratio", j, "modes[0].damping_sigma");
  j = ValidDataset();
  j["modes"][0].erase("shape");
  add("shape sigma without shape", j, "modes[0].shape_sigma");
  j = ValidDataset();
  j["modes"][0]["shape"] = {{"z_b", 0.0}};
  add("all-zero shape", j, "modes[0].shape");
  j = ValidDataset();
  j["initial"]["m_b"] = 2.0;
  add("known and initial", j, "initial.m_b");
  const struct { const char* what; const char* from; const char* to; const char* field; } ties[] = {
      {"tie to itself", "k_btheta", "k_btheta", "ties.k_btheta"},
      {"tie to an unknown parameter", "k_btheta", "k_nope", "ties.k_btheta"},
      {"tie from an unknown parameter", "k_nope", "k_bx", "ties.k_nope"},
      {"tie chain", "k_btheta", "k_bz", "ties.k_btheta"},
      {"tied and initial", "k_bx", "k_btheta", "ties.k_bx"}};
  for (const auto& t : ties) {
    j = ValidDataset();
    j["ties"][t.from] = t.to;
    add(t.what, j, t.field);
  }
  // Text that is not a dataset at all.
  const std::string valid = ValidDataset().dump();
  for (const auto& [what, text] : std::vector<std::pair<std::string, std::string>>{
           {"empty file", ""},
           {"truncated", valid.substr(0, valid.size() / 2)},
           {"binary", std::string("\x7f" "ELF\x02\x01\x01\0\0\xff\xfe", 12)},
           {"top level array", "[1, 2]"},
           {"duplicate key", R"({"name": "a", "name": "b"})"},
           {"nested too deep", std::string(100, '[') + std::string(100, ']')}}) {
    out.push_back({what, text, ""});
  }
  return out;
}

int StartRingid(const std::string& args, const std::string& err) {
  const std::string shell = "cd " + SourcePath("") + " && exec " + std::string(RINGID_BINARY) +
                            " " + args + " > /dev/null 2> " + err;
  const char* argv[] = {"/bin/sh", "-c", shell.c_str(), nullptr};
  pid_t pid = -1;
  EXPECT_EQ(posix_spawn(&pid, "/bin/sh", nullptr, nullptr, const_cast<char**>(argv), environ), 0);
  return pid;
}

int WaitFor(int pid) {
  int raw = 0;
  EXPECT_EQ(::waitpid(pid, &raw, 0), pid);
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

std::string Scratch(const std::string& name) {
  const std::string dir =
      ::testing::TempDir() + "ringid-test-" + std::to_string(::getpid()) + "/";
  ::mkdir(dir.c_str(), 0700);
  return dir + name;
}

RunResult Ringid(const std::string& args, const std::string& cwd) {
  const std::string err = Scratch("stderr.txt"), out = Scratch("stdout.txt");
  const std::string cmd = (cwd.empty() ? "" : "cd '" + cwd + "' && ") +
                          std::string(RINGID_BINARY) + " " + args + " > " + out + " 2> " + err;
  const int raw = std::system(cmd.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, ReadFile(err), ReadFile(out)};
}

bool Exists(const std::string& path) {
  struct stat st;
  return ::stat(path.c_str(), &st) == 0;
}

std::string ReadFile(const std::string& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

bool HaveProgram(const std::string& program) {
  return std::system(("command -v " + program + " > /dev/null 2>&1").c_str()) == 0;
}

bool InCi() {
  const char* ci = std::getenv("CI");
  return ci && *ci && std::string(ci) != "false" && std::string(ci) != "0";
}

}  // namespace ringid::testing
