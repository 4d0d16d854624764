// The length unit of a STEP file (ISO 10303-41 §4.2: SI_UNIT, CONVERSION_BASED_UNIT): what the
// coordinates of its geometry mean. ssimarch keeps the file's coordinates as they are (a model in
// millimetres is traced in millimetres) and reports the unit, which OpenCASCADE converts to mm
// silently; on request (`--unit`) a model is read converted to a named unit (issue 28 item 1).
#pragma once

#include <string>

#include "ssimarch/step/part21.hpp"

namespace ssimarch {

struct StepLengthUnit {
  std::string name = "unspecified";  ///< "millimetre", "metre", "inch", ...: as the file names it
  double metres = 0;                 ///< metres per unit; 0 when the file declares no length unit
  bool several = false;              ///< the file declares more than one distinct length unit
};

/// The length unit of the file's geometry: the unit its B-rep representations' contexts assign
/// (GLOBAL_UNIT_ASSIGNED_CONTEXT), else any context's, else the first LENGTH_UNIT instance; an
/// SI_UNIT with its prefix
/// (.MILLI. .METRE. = 0.001 m) or a CONVERSION_BASED_UNIT whose factor is a measure with an SI
/// unit ('INCH', 25.4 mm = 0.0254 m). Throws InputError naming the instance for a malformed one.
StepLengthUnit step_length_unit(const StepFile& file);

/// A length unit named by a user (`--unit`, a scene's "unit", Python's unit=): mm, cm, m, um, nm,
/// km, in, ft, or the names millimetre/millimeter, centimetre, metre/meter, micrometre/micron,
/// nanometre, kilometre, inch, foot, any case. Throws InputError(where) listing them otherwise.
StepLengthUnit named_length_unit(const std::string& text, const std::string& where);

/// Units of `to` per unit of `from` (25.4 from inch to millimetre). Throws InputError naming
/// `source` when `from` is unspecified (the file declares no length unit) or is several units.
double length_conversion(const StepLengthUnit& from, const StepLengthUnit& to, const std::string& source);

}  // namespace ssimarch
