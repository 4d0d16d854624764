// Shared by `trace` and `demo`: choosing output formats and writing traced runs.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "ssimarch/pipeline/trace_job.hpp"

namespace ssimarch::cli {

enum class OutputFormat { kJson, kCsv, kObj, kSvg, kStep, kVtp, kVtpAscii, kHtml };

/// "json", "csv", "obj", "svg", "step", "vtp", "vtp-ascii", "html"; throws CliError otherwise.
OutputFormat parse_format(const std::string& s);
/// From a file name's extension; json when it has none of the known ones.
OutputFormat format_from_path(const std::filesystem::path& p);

/// Writes runs in the format to `path` ("-" = standard output). SVG writes one file per run
/// (path itself when there is one run, else <stem>_<name>.svg beside it). VTP writes three files
/// (io/vtp_writer.hpp: <stem>.vtp, <stem>_points.vtp, <stem>.vtm), never to standard output.
/// HTML (the viewer page, docs/viewer.md) needs the scene for the surfaces' meshes.
void write_runs(const std::vector<IntersectionRun>& runs, OutputFormat format, const std::string& path,
                const Scene* scene = nullptr);

/// One line per curve on stderr: closed/open, length, points, time.
void print_summary(const std::vector<IntersectionRun>& runs);

}  // namespace ssimarch::cli
