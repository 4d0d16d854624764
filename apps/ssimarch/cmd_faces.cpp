// ssimarch faces MODEL.step: the faces of a STEP file, numbered as a scene names them
// ({"step": "MODEL.step", "face": N}, docs/scene-format.md), with their surface type and the
// parameter domain ssimarch gives them (io/step_reader.hpp), the box the placed surface lies in,
// as a table or JSON.
#include <algorithm>
#include <iostream>
#include <memory>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "run_budget.hpp"
#include "trace_flags.hpp"
#include "ssimarch/core/error.hpp"
#include "ssimarch/step/reader.hpp"
#include "ssimarch/step/units.hpp"

namespace ssimarch::cli {

namespace {

struct FacesArgs {
  std::string file;
  std::string unit;
  bool json = false;
};

nlohmann::json unit_json(const StepLengthUnit& u) {
  return {{"name", u.name}, {"metres", u.metres}, {"several", u.several}};
}

nlohmann::json face_json(const StepModel& model, const StepFace& f) {
  nlohmann::json j{{"face", f.index},          {"entity", f.entity}, {"line", f.line},
                   {"surface_entity", f.surface_entity}, {"step_type", f.surface_type}, {"same_sense", f.same_sense}};
  if (!f.instance.empty()) {
    // Where the assembly puts this occurrence: p -> rotation p + translation (rows of the rotation).
    const auto& R = f.placement.rotation;
    j["instance"] = f.instance;
    j["placement"] = {
        {"rotation", {{R(0, 0), R(0, 1), R(0, 2)}, {R(1, 0), R(1, 1), R(1, 2)}, {R(2, 0), R(2, 1), R(2, 2)}}},
        {"translation", {f.placement.translation.x(), f.placement.translation.y(), f.placement.translation.z()}}};
  }
  try {
    const Surface s = model.surface(f.entity, f.placement);
    const ParamDomain& d = s.domain();
    j["surface"] = std::string(s.type_name());
    j["u"] = {d.u.lo, d.u.hi};
    j["v"] = {d.v.lo, d.v.hi};
    j["periodic"] = {d.periodic_u, d.periodic_v};
    // Where the (placed) surface lies: a primitive's trimmed part, a patch's control points
    // (issue 28: which faces can meet is the first thing a user of a model asks).
    const Box& b = s.box();
    j["box"] = {{b.x.lo, b.y.lo, b.z.lo}, {b.x.hi, b.y.hi, b.z.hi}};
  } catch (const InputError& e) {
    j["error"] = e.what();
  }
  return j;
}

int run_faces(const FacesArgs& a) {
  const StepModel model = StepModel::read(a.file, input_limits(), unit_flag(a.unit));
  nlohmann::json list = nlohmann::json::array();
  for (const StepFace& f : model.faces()) list.push_back(face_json(model, f));
  // Issue 29: a file without faces listed an empty table with exit status 0.
  if (list.empty())
    throw InputError(a.file, "no faces (ADVANCED_FACE, FACE_SURFACE): the file holds no surface geometry to list");
  const auto unread =
      std::count_if(list.begin(), list.end(), [](const nlohmann::json& j) { return j.contains("error"); });
  const int status = unread > 0 ? 1 : 0;
  if (unread > 0)
    std::cerr << fmt::format("ssimarch: {} of {} face(s) of {} could not be read (see each face's error)\n", unread,
                             list.size(), a.file);
  // The unit the coordinates are in: the file's (kept as written) or the one --unit converted to.
  // A malformed unit is an error here, where the unit is listed (step_length_unit names it).
  if (!model.converted_to()) step_length_unit(model.file());
  const StepLengthUnit& unit = model.length_unit();
  const StepLengthUnit& file_unit = model.file_length_unit();
  if (file_unit.several && !model.converted_to())
    std::cerr << fmt::format("ssimarch: {} declares more than one length unit; the first, {}, is listed\n", a.file,
                             unit.name);
  if (a.json) {
    nlohmann::json out{{"file", a.file}, {"length_unit", unit_json(unit)}};
    if (model.converted_to()) out["converted_from"] = unit_json(file_unit);
    out["faces"] = list;
    std::cout << out.dump(2) << "\n";
    return status;
  }
  if (model.converted_to())
    std::cout << fmt::format("length unit: {} ({:g} m), converted from the file's {} (x {:.17g})\n", unit.name,
                             unit.metres, file_unit.name, model.length_scale());
  else if (unit.metres > 0)
    std::cout << fmt::format("length unit: {} ({:g} m); coordinates are kept in it (--unit converts)\n", unit.name,
                             unit.metres);
  else
    std::cout << "length unit: none declared; coordinates are kept as written\n";
  std::cout << fmt::format("{:>5} {:>9} {:>7}  {:<28} {}\n", "face", "entity", "line", "STEP surface", "ssimarch surface, domain");
  for (const auto& j : list) {
    std::string what;
    if (j.contains("error")) what = "not read: " + j["error"].get<std::string>();
    else
      what = fmt::format("{} u [{:.6g}, {:.6g}]{} v [{:.6g}, {:.6g}]{}", j["surface"].get<std::string>(), j["u"][0].get<double>(),
                         j["u"][1].get<double>(), j["periodic"][0].get<bool>() ? " periodic" : "", j["v"][0].get<double>(),
                         j["v"][1].get<double>(), j["periodic"][1].get<bool>() ? " periodic" : "");
    if (j.contains("box"))
      what += fmt::format(", box ({:.6g}, {:.6g}, {:.6g})-({:.6g}, {:.6g}, {:.6g})", j["box"][0][0].get<double>(),
                          j["box"][0][1].get<double>(), j["box"][0][2].get<double>(), j["box"][1][0].get<double>(),
                          j["box"][1][1].get<double>(), j["box"][1][2].get<double>());
    if (j.contains("instance")) what += ", placed as " + j["instance"].get<std::string>();
    std::cout << fmt::format("{:>5} {:>9} {:>7}  {:<28} {}\n", j["face"].get<int>(), "#" + std::to_string(j["entity"].get<std::int64_t>()),
                             j["line"].get<int>(), j["step_type"].get<std::string>(), what);
  }
  return status;
}

}  // namespace

void add_faces_command(CLI::App& app, Commands& commands) {
  auto args = std::make_shared<FacesArgs>();
  CLI::App* cmd = app.add_subcommand("faces", "List the faces of a STEP file (AP203/AP214/AP242) with their surfaces");
  cmd->footer(
      "A scene names a face as {\"step\": \"MODEL.step\", \"face\": N} or by its instance id, "
      "{\"step\": \"MODEL.step\", \"entity\": ID} (docs/scene-format.md, docs/cad.md). In an assembly a part's "
      "faces are listed once per placement, in the assembly's coordinates (\"face\": N is that occurrence); "
      "\"entity\" is the face in its part's own coordinates.");
  cmd->add_option("file", args->file, "STEP file (ISO 10303-21)")->required();
  cmd->add_flag("--json", args->json, "print JSON instead of a table");
  add_unit_option(cmd, &args->unit);
  add_budget_options(cmd);
  commands.add(cmd, [args] { return run_faces(*args); });
}

}  // namespace ssimarch::cli
