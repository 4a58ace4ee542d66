#include "apps/campaign.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

#include "apps/command_line.h"
#include "apps/html_report.h"
#include "apps/interrupt.h"
#include "apps/reports.h"
#include "estimation/parallel.h"
#include "estimation/problem.h"

namespace ringid {

namespace fs = std::filesystem;

bool ParseShard(const std::string& text, Shard* shard, std::string* error) {
  if (text == "slurm") {
    return SlurmShard([](const char* name) { return std::getenv(name); }, shard, error);
  }
  std::istringstream in(text);
  char slash = 0;
  std::string rest;
  if (!(in >> shard->index >> slash >> shard->count) || slash != '/' || (in >> rest) ||
      shard->count < 1 || shard->index < 0 || shard->index >= shard->count) {
    *error = "--shard: must be I/N with 0 <= I < N, or slurm, got '" + text + "'";
    return false;
  }
  return true;
}

bool SlurmShard(const std::function<const char*(const char*)>& getenv, Shard* shard,
                std::string* error) {
  const auto fail = [&](const std::string& why) {
    *error = "--shard=slurm: " + why;
    return false;
  };
  std::map<std::string, long> v;
  for (const char* name : {"ID", "COUNT", "MIN", "MAX", "STEP"}) {
    const std::string variable = std::string("SLURM_ARRAY_TASK_") + name;
    const char* text = getenv(variable.c_str());
    if (!text) continue;
    char* end = nullptr;
    errno = 0;
    const long value = std::strtol(text, &end, 10);
    if (!*text || *end || errno || value < 0 || value > (1L << 30)) {
      return fail(variable + " = '" + std::string(text).substr(0, 20) + "' is not a task number");
    }
    v[name] = value;
  }
  if (!v.count("ID")) {
    return fail("SLURM_ARRAY_TASK_ID is not set: not a task of a Slurm job array (sbatch --array)");
  }
  for (const char* name : {"COUNT", "MIN", "MAX"}) {
    if (!v.count(name)) return fail(std::string("SLURM_ARRAY_TASK_") + name + " is not set");
  }
  const long id = v["ID"], count = v["COUNT"], min = v["MIN"], max = v["MAX"];
  const long step = v.count("STEP") ? v["STEP"] : 1;
  const std::string array = std::to_string(min) + "-" + std::to_string(max) +
                            (step == 1 ? "" : ":" + std::to_string(step));
  if (step < 1 || max < min || (max - min) % step != 0 || (max - min) / step + 1 != count) {
    return fail("the array " + array + " of " + std::to_string(count) +
                " tasks is not an evenly stepped range (a list such as 1,3,7 is not): give "
                "--shard=I/N");
  }
  if (id < min || id > max || (id - min) % step != 0) {
    return fail("task " + std::to_string(id) + " is not in the array " + array);
  }
  shard->index = static_cast<int>((id - min) / step);
  shard->count = static_cast<int>(count);
  return true;
}

bool ListDatasets(const std::string& list, const Shard& shard, std::vector<std::string>* all_out,
                  std::vector<std::string>* files, std::string* error) {
  std::vector<std::string>& all = *all_out;
  all.clear();
  std::stringstream items(list);
  std::string path;
  while (std::getline(items, path, ',')) {
    if (path.empty()) continue;
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
      std::vector<std::string> in_dir;
      for (fs::directory_iterator it(path, ec), end; !ec && it != end; it.increment(ec)) {
        if (it->path().extension() == ".json" && it->is_regular_file(ec)) {
          in_dir.push_back(it->path().string());
        }
      }
      if (ec) {
        *error = path + ": cannot read directory: " + ec.message();
        return false;
      }
      std::sort(in_dir.begin(), in_dir.end());
      all.insert(all.end(), in_dir.begin(), in_dir.end());
    } else if (fs::exists(path, ec)) {
      all.push_back(path);
    } else {
      *error = path + ": no such file or directory";
      return false;
    }
  }
  if (all.empty()) {
    *error = "--dataset: no dataset listed in '" + list + "'";
    return false;
  }
  files->clear();
  for (size_t i = shard.index; i < all.size(); i += shard.count) files->push_back(all[i]);
  return true;
}

bool ReportNames(const std::vector<std::string>& files, const std::string& dir,
                 std::vector<std::string>* reports, std::string* error) {
  std::map<std::string, std::string> seen;
  reports->clear();
  for (const std::string& f : files) {
    const std::string stem = fs::path(f).stem().string();
    const std::string summaries = kCampaignSummaryStem;
    const bool summary = stem == summaries || stem.rfind(summaries + ".", 0) == 0;
    if (summary || seen.count(stem)) {
      *error = f + ": its report " + stem + ".json would overwrite " +
               (summary ? "a campaign summary" : "that of " + seen[stem]);
      return false;
    }
    seen[stem] = f;
    reports->push_back((fs::path(dir) / (stem + ".json")).string());
  }
  return true;
}

CampaignRow IdentifyRow(const IdentifyResult& s) {
  CampaignRow row;
  row.status = s.status;
  row.converged = s.converged;
  row.cost = s.cost;
  row.relative_error_in_plane_eq19 = s.relative_error_in_plane;
  row.relative_error_out_of_plane_eq20 = s.relative_error_out_of_plane;
  row.seconds = s.seconds;
  std::map<Param, double> values;
  for (const ParameterEstimate& e : s.estimates) {
    if (e.free && !values.count(e.key.param)) values[e.key.param] = e.value;
  }
  if (s.status.ok()) row.parameters = values;
  return row;
}

CampaignRow DiagnoseRow(const DiagnosisResult& r) {
  CampaignRow row;
  row.status = r.status;
  row.seconds = r.seconds;
  if (r.status.ok()) {
    row.verdict = r.verdict;
    row.indistinguishable = r.indistinguishable;
    row.gap_before = row.gap_after = r.gap_before;
    row.shrink = 0;
    for (const EffectFit& f : r.ranking) {
      if (f.effect == r.verdict) row.gap_after = f.gap_after, row.shrink = f.shrink;
    }
  }
  return row;
}

namespace {

// The row of a report kept from an earlier run: read back whole, made from
// `dataset`'s bytes under `options`; false otherwise.
bool KeptRow(ReportKind command, const std::string& path, const std::string& dataset,
             const std::vector<std::string>& options, CampaignRow* row) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return false;
  Json json;
  std::string why;
  if (!LoadReport(path, &json, &why)) return false;
  static const std::string version = MakeProvenance(0, nullptr, {}, std::nullopt).ringid_version;
  const auto same_source = [&](const Provenance& p) {
    if (!p.options || *p.options != options || p.ringid_version != version) return false;
    for (const InputFile& f : p.inputs) {
      if (f.role == "dataset") return !f.sha256.empty() && f.sha256 == FileSha256(dataset);
    }
    return false;
  };
  if (command == ReportKind::kIdentify) {
    IdentifyReport r;
    if (!ReadReport(json, &r, &why) || !same_source(r.provenance)) return false;
    *row = IdentifyRow(r.body.result);
  } else {
    DiagnoseReport r;
    if (!ReadReport(json, &r, &why) || !same_source(r.provenance)) return false;
    *row = DiagnoseRow(r.body.result);
  }
  row->resumed = true;
  return true;
}

// What an interrupted campaign kept: the reports finished whole (each is
// written as its dataset finishes), and whether the summary was written.
std::string CampaignKept(const std::vector<std::string>& written,
                         const std::vector<std::string>& reports, const std::string& summary) {
  std::string names;
  int finished = 0;
  bool summarised = false;
  for (const std::string& w : written) {
    if (w == summary) {
      summarised = true;
    } else if (std::find(reports.begin(), reports.end(), w) != reports.end()) {
      names += (finished++ ? ", " : "") + std::filesystem::path(w).filename().string();
    }
  }
  const std::string dir = std::filesystem::path(summary).parent_path().string();
  const std::string of = " of " + std::to_string(reports.size()) + " report(s)";
  if (finished == 0) return "none" + of + " finished; nothing written in " + dir;
  return "kept the " + std::to_string(finished) + of + " finished whole, in " + dir + ": " +
         names + "; " + std::filesystem::path(summary).filename().string() +
         (summarised ? " written" : " not written");
}

// The datasets a campaign cannot use, as one line: every one named, or the
// first kNamed and how many more.
std::string BadDatasets(const std::vector<std::string>& bad) {
  constexpr size_t kNamed = 5;
  if (bad.size() == 1) return bad[0];
  std::string line = std::to_string(bad.size()) + " datasets cannot be used (--keep_going runs "
                     "the others, these as failed rows): ";
  for (size_t i = 0; i < bad.size() && i < kNamed; ++i) line += (i ? "; " : "") + bad[i];
  if (bad.size() > kNamed) line += "; and " + std::to_string(bad.size() - kNamed) + " more";
  return line;
}

}  // namespace

int RunCampaign(const CampaignRequest& request, const ModalModel& model,
                const CampaignWork& work, std::string* error) {
  const auto usage = [&](const std::string& line) {
    *error = line;
    return kExitUsage;
  };
  Shard shard;
  if (request.jobs < 1) return usage("--jobs: must be at least 1");
  if (!ParseShard(request.shard, &shard, error)) return kExitUsage;
  std::vector<std::string> all, files, reports;
  if (!ListDatasets(request.datasets, shard, &all, &files, error)) return kExitUsage;
  // Named over the whole list: shards write into one directory.
  std::vector<std::string> all_reports;
  if (!ReportNames(all, request.output_dir, &all_reports, error)) return kExitUsage;
  for (size_t i = shard.index; i < all_reports.size(); i += shard.count) {
    reports.push_back(all_reports[i]);
  }
  for (size_t i = 0; i < reports.size(); ++i) {  // --output_dir=the datasets' own directory
    for (const std::string& f : files) {
      if (SameFile(reports[i], f)) {
        return usage("--output_dir: " + reports[i] + ", the report of " + files[i] +
                     ", would overwrite the dataset " + f);
      }
    }
  }
  const std::string shard_name = std::to_string(shard.index) + "/" + std::to_string(shard.count);
  const std::string summary_path =
      (std::filesystem::path(request.output_dir) / CampaignSummaryName(shard.index, shard.count))
          .string();
  const int n = static_cast<int>(files.size());
  std::vector<Dataset> datasets(n);
  std::vector<CampaignItem> items(n);
  std::vector<bool> done(n, false);  // failed to load (--keep_going) or kept
  std::vector<std::string> bad;      // why each dataset that cannot be used
  for (int i = 0; i < n; ++i) {
    LoadError load;
    std::string why;
    Status status;  // a dataset the model cannot start on
    if (!LoadDataset(files[i], &datasets[i], &load)) {
      why = load.OneLine();
      items[i].row.field = load.field;
    } else if (request.prepare && !request.prepare(&datasets[i], &why)) {
      why = files[i] + ": " + why;
      items[i].row.field = "";
    } else if (!Problem::Create(model, datasets[i], ResidualOptions(), &status)) {
      why = files[i] + ": " + status.message;
      items[i].row.field = "";
    }
    if (why.empty()) continue;
    bad.push_back(why);
    items[i].row.status = Status::InvalidInput(why);
    done[i] = true;
  }
  if (!bad.empty() && !request.keep_going) return usage(BadDatasets(bad));
  std::error_code ec;
  std::filesystem::create_directories(request.output_dir, ec);
  if (ec) return usage("--output_dir: " + request.output_dir + ": " + ec.message());
  for (const std::string& out : reports) {
    if (!CanWrite(out, error)) return usage("--output_dir: " + *error);
  }
  if (!CanWrite(summary_path, error)) return usage("--output_dir: " + *error);
  int resumed = 0;
  for (int i = 0; i < n; ++i) {
    if (done[i] || request.force) continue;
    if (KeptRow(request.command, reports[i], files[i], request.options, &items[i].row)) {
      done[i] = true;
      ++resumed;
    }
  }
  std::vector<int> to_run;
  for (int i = 0; i < n; ++i) {
    if (!done[i]) to_run.push_back(i);
  }
  const KeptNote kept([&](const std::vector<std::string>& written) {
    return CampaignKept(written, reports, summary_path);
  });
  std::vector<std::string> write_errors(n);
  const auto t0 = std::chrono::steady_clock::now();
  {
    Progress progress(ToString(request.command), static_cast<int>(to_run.size()));
    internal::ParallelFor(static_cast<int>(to_run.size()), request.jobs, [&](int k) {
      const int i = to_run[k];
      items[i] = work(datasets[i], files[i]);
      WriteFileAtomically(reports[i], items[i].report, &write_errors[i]);
      progress.Add();
    });
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (const std::string& e : write_errors) {
    if (!e.empty()) return usage(e);
  }
  std::vector<std::pair<std::string, std::string>> inputs;
  for (int i = 0; i < n; ++i) {
    if (!items[i].row.field) inputs.emplace_back("dataset", files[i]);
  }
  CampaignReport summary{request.provenance(inputs),
                         {request.command, shard_name, request.jobs, seconds, {}}};
  summary.body.campaign_datasets = all;
  summary.body.options = request.options;
  summary.body.resumed = resumed;
  bool all_ok = true;
  for (int i = 0; i < n; ++i) {
    items[i].row.dataset = files[i];
    items[i].row.report_file = items[i].row.field ? "" : reports[i];
    all_ok &= items[i].row.status.ok();
    summary.body.failed += items[i].row.status.ok() ? 0 : 1;
    summary.body.datasets.push_back(items[i].row);
  }
  std::printf("%s\n%d dataset(s), %d job(s), %.1f s; %d kept from an earlier run, %d failed; "
              "reports in %s\n",
              CampaignTable(summary.body).c_str(), n, request.jobs, seconds, resumed,
              summary.body.failed, request.output_dir.c_str());
  if (!WriteFileAtomically(summary_path, ReportText(summary), error)) return kExitUsage;
  return all_ok ? kExitOk : kExitFailure;
}

}  // namespace ringid
