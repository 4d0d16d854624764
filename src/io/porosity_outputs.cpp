// The files of a porosity run (see porosity_outputs.hpp).
#include "ssimarch/io/porosity_outputs.hpp"

#include <limits>
#include <utility>
#include <vector>

#include "ssimarch/core/error.hpp"
#include "ssimarch/io/porosity_vtk.hpp"
#include "ssimarch/io/profile_plot.hpp"

namespace ssimarch {

namespace {

void write_csv(OutputFiles& files, const std::string& path, const std::string& header,
               const std::vector<std::vector<double>>& cols) {
  std::ostream& out = files.open(path.empty() ? "-" : path);
  out << header << "\n";
  out.precision(std::numeric_limits<double>::max_digits10);
  for (std::size_t i = 0; i < cols[0].size(); ++i) {
    for (std::size_t c = 0; c < cols.size(); ++c) out << (c ? "," : "") << cols[c][i];
    out << "\n";
  }
}

nlohmann::json stats_json(const ProfileStats& s) {
  return {{"evaluations", s.evaluations}, {"unconverged", s.unconverged}, {"max_error_estimate", s.max_error}};
}

nlohmann::json write_csv_profiles(OutputFiles& files, const std::string& output, const PorosityJobResult& r) {
  nlohmann::json outputs = nlohmann::json::object();
  int emitted = 0;
  auto next_out = [&](const char* suffix) { return emitted++ == 0 ? output : derived_path(output, suffix).string(); };
  auto entry = [](const std::string& path, const char* columns, nlohmann::json n) {
    return nlohmann::json{{"file", path.empty() ? "-" : path}, {"columns", columns}, {"n", std::move(n)}};
  };
  if (r.radial) {
    const std::string path = next_out("radial");
    write_csv(files, path, "r,porosity", {r.radial->x, r.radial->porosity});
    outputs["radial"] = entry(path, "r,porosity", r.radial->x.size());
    outputs["radial"]["stats"] = stats_json(r.radial->stats);
  } else if (r.bins) {
    const std::string path = next_out("radial");
    write_csv(files, path, "r_inner,r_outer,porosity", {r.bins->x, r.bins->x_upper, r.bins->porosity});
    outputs["bins"] = entry(path, "r_inner,r_outer,porosity", r.bins->x.size());
    outputs["bins"]["stats"] = stats_json(r.bins->stats);
  }
  if (r.axial) {
    const std::string path = next_out("axial");
    write_csv(files, path, "z,porosity", {r.axial->x, r.axial->porosity});
    outputs["axial"] = entry(path, "z,porosity", r.axial->x.size());
    outputs["axial"]["stats"] = stats_json(r.axial->stats);
  }
  if (r.map) {
    const std::string path = next_out("map");
    std::vector<double> cr, cz;
    for (double z : r.map->z)
      for (double rr : r.map->r) cr.push_back(rr), cz.push_back(z);
    write_csv(files, path, "r,z,porosity", {cr, cz, r.map->porosity});
    outputs["map"] = entry(path, "r,z,porosity", {r.map->r.size(), r.map->z.size()});
  }
  return outputs;
}

nlohmann::json write_vtk_profiles(OutputFiles& files, const std::filesystem::path& out, VtkEncoding enc,
                                  const PorosityJobResult& r) {
  bool output_used = false;
  std::vector<std::pair<std::string, std::string>> blocks;
  nlohmann::json outputs = nlohmann::json::object();
  auto path_for = [&](const char* suffix, const char* ext) {
    if (!output_used && out.extension() == ext) {
      output_used = true;
      return out;
    }
    return out.parent_path() / (out.stem().string() + "_" + suffix + ext);
  };
  auto put = [&](const char* key, const std::filesystem::path& p, const char* arrays, nlohmann::json n) {
    blocks.emplace_back(key, p.filename().string());
    outputs[key] = {
        {"file", p.string()}, {"format", p.extension().string().substr(1)}, {"columns", arrays}, {"n", std::move(n)}};
  };
  if (r.radial) {
    const auto p = path_for("radial", ".vtp");
    write_vtp(files.open(p), radial_profile_poly_data(*r.radial, r.container), enc);
    put("radial", p, "r,porosity", r.radial->x.size());
    outputs["radial"]["stats"] = stats_json(r.radial->stats);
  } else if (r.bins) {
    const auto p = path_for("radial", ".vtp");
    write_vtp(files.open(p), bin_profile_poly_data(*r.bins, r.container), enc);
    put("bins", p, "r_inner,r_outer,porosity", r.bins->x.size());
    outputs["bins"]["stats"] = stats_json(r.bins->stats);
  }
  if (r.axial) {
    const auto p = path_for("axial", ".vtp");
    write_vtp(files.open(p), axial_profile_poly_data(*r.axial), enc);
    put("axial", p, "z,porosity", r.axial->x.size());
    outputs["axial"]["stats"] = stats_json(r.axial->stats);
  }
  if (r.map) {
    const auto p = path_for("map", ".vti");
    write_vti(files.open(p), porosity_map_image_data(*r.map), enc);
    put("map", p, "porosity", {r.map->r.size(), r.map->z.size()});
  }
  if (out.extension() != ".vtp" && out.extension() != ".vti") {
    const std::filesystem::path vtm = out.parent_path() / (out.stem().string() + ".vtm");
    write_vtm(files.open(vtm), blocks);
    outputs["multiblock"] = vtm.string();
  }
  return outputs;
}

}  // namespace

PorosityFileFormat porosity_file_format(std::string_view name, const std::filesystem::path& output,
                                        const std::string& where) {
  if (name.empty()) {
    const std::string e = output.extension().string();
    return e == ".vtm" || e == ".vtp" || e == ".vti" ? PorosityFileFormat::kVtk : PorosityFileFormat::kCsv;
  }
  if (name == "csv") return PorosityFileFormat::kCsv;
  if (name == "vtk") return PorosityFileFormat::kVtk;
  if (name == "vtk-ascii") return PorosityFileFormat::kVtkAscii;
  throw InputError(where, "must be csv, vtk or vtk-ascii, got '" + std::string(name) + "'");
}

std::filesystem::path derived_path(const std::filesystem::path& base, std::string_view suffix) {
  return base.parent_path() / (base.stem().string() + "_" + std::string(suffix) + base.extension().string());
}

nlohmann::json write_porosity_profiles(OutputFiles& files, const std::string& output, PorosityFileFormat format,
                                       const PorosityJobResult& r) {
  if (format == PorosityFileFormat::kCsv) return write_csv_profiles(files, output, r);
  return write_vtk_profiles(files, output,
                            format == PorosityFileFormat::kVtkAscii ? VtkEncoding::kAscii : VtkEncoding::kBase64, r);
}

void write_porosity_plot(OutputFiles& files, const std::filesystem::path& path, const PorosityJobResult& r,
                         std::string_view packing_name) {
  ProfilePlot plot;
  if (r.radial) {
    plot.series.push_back({"exact radial porosity", r.radial->x, r.radial->porosity, "#1f77b4", false});
    plot.xlabel = "r";
  } else if (r.bins) {
    plot.series.push_back(staircase("exact annular-bin porosity", r.bins->x, r.bins->x_upper, r.bins->porosity));
    plot.xlabel = "r";
  } else if (r.axial) {
    plot.series.push_back({"exact axial porosity", r.axial->x, r.axial->porosity, "#1f77b4", false});
    plot.xlabel = "z";
  }
  plot.title = "Porosity profile of " + std::string(packing_name);
  plot.ylabel = "porosity";
  write_profile_plot(files.open(path), plot);
}

nlohmann::json porosity_summary_json(const PorosityJob& job, const PorosityJobResult& r,
                                     std::string_view packing_name) {
  nlohmann::json js;
  js["packing"] = packing_name;
  js["particles"] = r.particles;
  // Rows grouped into clumped particles (a clump column): how many particles they form.
  if (r.clumped_particles > 0) js["clumped_particles"] = r.clumped_particles;
  js["particle_type"] = r.spherocylinders ? "spherocylinder" : "sphere";
  js["container_radius"] = r.container.radius;
  js["z_range"] = {r.container.slab.z_min, r.container.slab.z_max};
  js["tolerance"] = job.options.tolerance;
  js["method"] = job.options.method == ProfileMethod::kKernel ? "kernel" : "chord";
  js["bulk_porosity"] = r.bulk.porosity;
  js["solid_volume"] = r.bulk.solid_volume;
  js["particles_in_container"] = r.bulk.stats.particles_used;
  js["particles_clipped"] = r.bulk.stats.particles_clipped;
  const std::pair<const char*, const std::optional<double>*> stages[] = {
      {"bulk", &r.timings.bulk}, {"radial", &r.timings.radial}, {"axial", &r.timings.axial}, {"map", &r.timings.map}};
  for (const auto& [name, t] : stages)
    if (*t) js["timings_s"][name] = **t;
  js["unconverged_integrals"] = r.unconverged;
  js["overlaps"] = {{"rule", to_string(job.options.overlaps)},
                    {"pairs", r.overlaps.pairs},
                    {"max_depth", r.overlaps.max_depth},
                    {"doubled_volume", r.overlaps.doubled_volume},
                    {"groups", r.bulk.stats.overlap_groups}};
  if (r.clumped_particles > 0) {
    js["overlaps"]["within_clumps"] = {{"pairs", r.overlaps.clump_pairs},
                                       {"doubled_volume", r.overlaps.clump_doubled_volume}};
  }
  return js;
}

}  // namespace ssimarch
