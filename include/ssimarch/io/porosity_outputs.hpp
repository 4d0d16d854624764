// The files of a porosity run (docs/output-format.md, "Porosity"): each profile as CSV or VTK XML,
// the SVG plot of the first 1-D profile and the JSON summary. The CLI's `ssimarch porosity` names
// the files; what goes into them is decided here, once, for every front end.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "ssimarch/io/output_files.hpp"
#include "ssimarch/pipeline/porosity_job.hpp"

namespace ssimarch {

/// How the profiles are written: CSV, or VTK XML with base64 binary or ASCII arrays.
enum class PorosityFileFormat { kCsv, kVtk, kVtkAscii };

/// The format named `name` ("csv", "vtk", "vtk-ascii"), or, when `name` is empty, the one `output`'s
/// extension implies (.vtm, .vtp, .vti: VTK; else CSV). Throws InputError(where, ...) for another name.
PorosityFileFormat porosity_file_format(std::string_view name, const std::filesystem::path& output,
                                        const std::string& where);

/// `base` with "_suffix" before its extension: run.csv, "axial" -> run_axial.csv.
std::filesystem::path derived_path(const std::filesystem::path& base, std::string_view suffix);

/// Writes every profile of `r` and returns the summary's "outputs" object (file, columns, n, stats
/// per profile). CSV: the first profile to `output` ("" or "-": standard output), the others to
/// files named after it (derived_path: _axial, _map). VTK: a 1-D profile as a .vtp polyline, the map
/// as .vti image data; `output` takes the first of its own extension, the others are named beside
/// it, and unless it is .vtp or .vti a .vtm of its stem lists them all.
nlohmann::json write_porosity_profiles(OutputFiles& files, const std::string& output, PorosityFileFormat format,
                                       const PorosityJobResult& r);

/// The SVG plot of the first 1-D profile: radial or bins against r, else axial against z.
void write_porosity_plot(OutputFiles& files, const std::filesystem::path& path, const PorosityJobResult& r,
                         std::string_view packing_name);

/// The JSON summary: packing, particles, container, accuracy, bulk porosity, timings, overlaps.
nlohmann::json porosity_summary_json(const PorosityJob& job, const PorosityJobResult& r, std::string_view packing_name);

}  // namespace ssimarch
