// The length unit of a STEP file (ISO 10303-41 §4.2: SI_UNIT, CONVERSION_BASED_UNIT): what the
// coordinates of its geometry mean. ssimarch keeps the file's coordinates as they are (a model in
// millimetres is traced in millimetres) and reports the unit, which OpenCASCADE converts to mm
// silently (issue 28 item 1).
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

}  // namespace ssimarch
