#include "apps/campaign.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

#include "apps/command_line.h"
#include "apps/interrupt.h"
#include "apps/reports.h"
#include "estimation/parallel.h"
#include "estimation/problem.h"

namespace ringid {

namespace fs = std::filesystem;

bool ParseShard(const std::string& text, Shard* shard, std::string* error) {
  std::istringstream in(text);
  char slash = 0;
  std::string rest;
  if (!(in >> shard->index >> slash >> shard->count) || slash != '/' || (in >> rest) ||
      shard->count < 1 || shard->index < 0 || shard->index >= shard->count) {
    *error = "--shard: must be I/N with 0 <= I < N, got '" + text + "'";
    return false;
  }
  return true;
}

bool ListDatasets(const std::string& list, const Shard& shard,
                  std::vector<std::string>* files, std::string* error) {
  std::vector<std::string> all;
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
    if (stem == "campaign" || seen.count(stem)) {
      *error = f + ": its report " + stem + ".json would overwrite " +
               (stem == "campaign" ? "the campaign summary" : "that of " + seen[stem]);
      return false;
    }
    seen[stem] = f;
    reports->push_back((fs::path(dir) / (stem + ".json")).string());
  }
  return true;
}

namespace {

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
  std::vector<std::string> files, reports;
  if (!ListDatasets(request.datasets, shard, &files, error)) return kExitUsage;
  if (!ReportNames(files, request.output_dir, &reports, error)) return kExitUsage;
  for (size_t i = 0; i < reports.size(); ++i) {  // --output_dir=the datasets' own directory
    for (const std::string& f : files) {
      if (SameFile(reports[i], f)) {
        return usage("--output_dir: " + reports[i] + ", the report of " + files[i] +
                     ", would overwrite the dataset " + f);
      }
    }
  }
  const std::string summary_path =
      (std::filesystem::path(request.output_dir) /
       (shard.count == 1 ? std::string("campaign.json")
                         : "campaign." + std::to_string(shard.index) + "-of-" +
                               std::to_string(shard.count) + ".json")).string();
  std::vector<Dataset> datasets(files.size());
  for (size_t i = 0; i < files.size(); ++i) {
    LoadError load;
    if (!LoadDataset(files[i], &datasets[i], &load)) return usage(load.OneLine());
    if (request.prepare && !request.prepare(&datasets[i], error)) return kExitUsage;
    Status status;  // a dataset the model cannot start on
    if (!Problem::Create(model, datasets[i], ResidualOptions(), &status)) {
      return usage(files[i] + ": " + status.message);
    }
  }
  std::error_code ec;
  std::filesystem::create_directories(request.output_dir, ec);
  if (ec) return usage("--output_dir: " + request.output_dir + ": " + ec.message());
  for (const std::string& out : reports) {
    if (!CanWrite(out, error)) return usage("--output_dir: " + *error);
  }
  if (!CanWrite(summary_path, error)) return usage("--output_dir: " + *error);
  const int n = static_cast<int>(files.size());
  const KeptNote kept([&](const std::vector<std::string>& written) {
    return CampaignKept(written, reports, summary_path);
  });
  std::vector<CampaignItem> items(n);
  std::vector<std::string> write_errors(n);
  const auto t0 = std::chrono::steady_clock::now();
  {
    Progress progress(ToString(request.command), n);
    internal::ParallelFor(n, request.jobs, [&](int i) {
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
  for (const std::string& f : files) inputs.emplace_back("dataset", f);
  CampaignReport summary{request.provenance(inputs),
                         {request.command, request.shard, request.jobs, seconds, {}}};
  bool all_ok = true;
  for (int i = 0; i < n; ++i) {
    items[i].row.dataset = files[i];
    items[i].row.report_file = reports[i];
    all_ok &= items[i].row.status.ok();
    summary.body.datasets.push_back(items[i].row);
  }
  std::printf("%s\n%d dataset(s), %d job(s), %.1f s; reports in %s\n",
              CampaignTable(summary.body).c_str(), n, request.jobs, seconds,
              request.output_dir.c_str());
  if (!WriteFileAtomically(summary_path, ReportText(summary), error)) return kExitUsage;
  return all_ok ? kExitOk : kExitFailure;
}


}  // namespace ringid
