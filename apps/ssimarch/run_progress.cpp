#include "run_progress.hpp"

#include <cstdio>
#include <map>
#include <string>

namespace ssimarch::cli {

namespace {
ProgressMode g_mode = ProgressMode::kAuto;
}

void add_progress_option(CLI::App* cmd) {
  static const std::map<std::string, ProgressMode> kModes = {
      {"auto", ProgressMode::kAuto}, {"bar", ProgressMode::kBar}, {"json", ProgressMode::kJson}, {"none", ProgressMode::kNone}};
  cmd->add_option_function<std::string>(
         "--progress", [](const std::string& m) { g_mode = kModes.at(m); },
         "progress on stderr: auto (a bar with rate and time left when stderr is a terminal, else nothing; default), "
         "bar, json (one JSON object a line, docs/output-format.md) or none")
      ->check(CLI::IsMember({"auto", "bar", "json", "none"}))
      ->type_name("MODE");
}

RunProgress::RunProgress(bool quiet)
    : sink_(quiet ? nullptr : make_progress_sink(g_mode, stderr)), meter_(sink_.get()), scope_(&meter_) {}

RunProgress::~RunProgress() { meter_.close(); }

}  // namespace ssimarch::cli
