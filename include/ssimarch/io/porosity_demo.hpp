// Porosity demo for `ssimarch demo`: a drop-and-roll sphere bed (container/particle diameter ratio 10),
// its exact radial profile, CSV files and an SVG plot against the de Klerk (2003) correlation.
#pragma once

#include <filesystem>
#include <ostream>
#include <string_view>

namespace ssimarch {

/// Writes into out_dir: packing.csv, radial_profile.csv (r,porosity), bins.csv
/// (r_inner,r_outer,porosity), radial_profile.svg and summary.json; logs progress lines to `log`.
/// With the viewer's script (docs/viewer.md) also an axial profile, an r-z map and bed.html, the
/// viewer page of the bed and its profiles. Takes about 10 s on 2 cores. Throws InputError (located
/// by the path) when a file cannot be written.
void run_porosity_demo(const std::filesystem::path& out_dir, std::ostream& log, std::string_view viewer_script = {});

}  // namespace ssimarch
