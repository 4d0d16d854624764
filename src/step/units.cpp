#include "ssimarch/step/units.hpp"

#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "access.hpp"
#include "ssimarch/core/text_cat.hpp"

namespace ssimarch {

using internal::cat;
using internal::StepAccess;

namespace {

// ISO 10303-41 si_prefix, as powers of ten.
constexpr std::array<std::pair<const char*, int>, 16> kPrefixes{{{"EXA", 18},
                                                                 {"PETA", 15},
                                                                 {"TERA", 12},
                                                                 {"GIGA", 9},
                                                                 {"MEGA", 6},
                                                                 {"KILO", 3},
                                                                 {"HECTO", 2},
                                                                 {"DECA", 1},
                                                                 {"DECI", -1},
                                                                 {"CENTI", -2},
                                                                 {"MILLI", -3},
                                                                 {"MICRO", -6},
                                                                 {"NANO", -9},
                                                                 {"PICO", -12},
                                                                 {"FEMTO", -15},
                                                                 {"ATTO", -18}}};

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return s;
}

// An SI_UNIT of length: (prefix or $, .METRE.).
StepLengthUnit si_length(const StepAccess& a, const StepInstance& u, const StepRecord& si) {
  const StepValue& prefix = a.param(u, si, 0, "prefix");
  const StepValue& name = a.param(u, si, 1, "name");
  if (name.kind != StepValue::Kind::kEnum || name.text != "METRE") a.fail(u, "a length unit must be the METRE");
  StepLengthUnit r{"metre", 1.0, false};
  if (prefix.kind == StepValue::Kind::kEnum) {
    bool known = false;
    for (const auto& [text, power] : kPrefixes)
      if (prefix.text == text) {
        r.name = lower(prefix.text) + "metre";
        r.metres = std::pow(10.0, power);
        known = true;
      }
    if (!known) a.fail(u, cat("unknown SI prefix .", prefix.text, "."));
  } else if (prefix.kind != StepValue::Kind::kUnset) {
    a.fail(u, "the prefix of an SI_UNIT must be an enumeration such as .MILLI. or $");
  }
  return r;
}

StepLengthUnit length_unit_of(const StepAccess& a, const StepInstance& u, int depth);

// A CONVERSION_BASED_UNIT('INCH', #m) with #m = LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE(25.4), #mm).
StepLengthUnit converted_length(const StepAccess& a, const StepInstance& u, const StepRecord& conv, int depth) {
  const StepValue& name = a.param(u, conv, 0, "name");
  const StepInstance& m = a.ref(u, a.param(u, conv, 1, "conversion_factor"), "conversion_factor");
  const StepRecord& mr = m.records.front();
  const double value = a.number(m, a.param(m, mr, 0, "value_component"), "value_component");
  const StepLengthUnit base =
      length_unit_of(a, a.ref(m, a.param(m, mr, 1, "unit_component"), "unit_component"), depth + 1);
  if (!(value > 0) || !std::isfinite(value)) a.fail(m, "a length unit's conversion factor must be > 0");
  return {name.kind == StepValue::Kind::kString ? lower(name.text) : "converted unit", value * base.metres, false};
}

StepLengthUnit length_unit_of(const StepAccess& a, const StepInstance& u, int depth) {
  if (depth > 8) a.fail(u, "length units refer to each other in a cycle");
  if (const StepRecord* si = u.record("SI_UNIT")) return si_length(a, u, *si);
  if (const StepRecord* conv = u.record("CONVERSION_BASED_UNIT")) return converted_length(a, u, *conv, depth);
  a.fail(u, "a length unit must be an SI_UNIT or a CONVERSION_BASED_UNIT");
}

// The length units of a context instance (GLOBAL_UNIT_ASSIGNED_CONTEXT's units), appended to `out`.
void context_length_units(const StepAccess& a, const StepInstance& context, std::vector<const StepInstance*>* out) {
  const StepRecord* assigned = context.record("GLOBAL_UNIT_ASSIGNED_CONTEXT");
  if (!assigned) return;
  for (const StepValue& v : a.list(context, a.param(context, *assigned, 0, "units"), "units")) {
    const StepInstance& u = a.ref(context, v, "units");
    if (u.record("LENGTH_UNIT")) out->push_back(&u);
  }
}

// A representation (name, items, context_of_items) whose items are the model's geometry
// (ADVANCED_BREP_SHAPE_REPRESENTATION, MANIFOLD_SURFACE_SHAPE_REPRESENTATION, ...): not the plain
// SHAPE_REPRESENTATION of a product's placements, nor CONTEXT_DEPENDENT_SHAPE_REPRESENTATION (a
// relationship, not a representation).
bool holds_geometry(const StepInstance& inst) {
  const StepRecord& r = inst.records.front();
  const std::string suffix = "_SHAPE_REPRESENTATION";
  const std::string& t = r.type;
  return inst.records.size() == 1 && t != "CONTEXT_DEPENDENT_SHAPE_REPRESENTATION" && t.size() > suffix.size() &&
         t.compare(t.size() - suffix.size(), suffix.size(), suffix) == 0 && r.params.size() >= 3 &&
         r.params[1].kind == StepValue::Kind::kList && r.params[2].kind == StepValue::Kind::kRef;
}

// The length units that measure the geometry: those of the contexts of the representations that
// hold it; else those every context assigns; else every LENGTH_UNIT instance. An inch file also
// holds the millimetre its inch is defined by, and an assembly a context per part.
std::vector<const StepInstance*> assigned_length_units(const StepAccess& a, const StepFile& file) {
  std::vector<const StepInstance*> geometric, assigned, all;
  for (std::int64_t id : file.order) {
    const StepInstance& inst = *file.find(id);
    if (inst.record("LENGTH_UNIT")) all.push_back(&inst);
    context_length_units(a, inst, &assigned);
    if (holds_geometry(inst))
      context_length_units(
          a, a.ref(inst, a.param(inst, inst.records.front(), 2, "context_of_items"), "context_of_items"), &geometric);
  }
  return !geometric.empty() ? geometric : !assigned.empty() ? assigned : all;
}

}  // namespace

StepLengthUnit step_length_unit(const StepFile& file) {
  const StepAccess a(file);
  StepLengthUnit first;
  bool found = false;
  for (const StepInstance* u : assigned_length_units(a, file)) {
    const StepLengthUnit unit = length_unit_of(a, *u, 0);
    if (!found) {
      first = unit;
      found = true;
    } else if (std::fabs(unit.metres - first.metres) > 1e-12 * first.metres) {
      first.several = true;
    }
  }
  return first;
}

namespace {

struct NamedUnit {
  const char* names[4];  // the symbol, then spellings ("" for none)
  const char* reported;
  double metres;
};
constexpr std::array<NamedUnit, 8> kNamedUnits{{{{"nm", "nanometre", "nanometer", ""}, "nanometre", 1e-9},
                                                {{"um", "micrometre", "micrometer", "micron"}, "micrometre", 1e-6},
                                                {{"mm", "millimetre", "millimeter", ""}, "millimetre", 1e-3},
                                                {{"cm", "centimetre", "centimeter", ""}, "centimetre", 1e-2},
                                                {{"m", "metre", "meter", ""}, "metre", 1.0},
                                                {{"km", "kilometre", "kilometer", ""}, "kilometre", 1e3},
                                                {{"in", "inch", "inches", ""}, "inch", 0.0254},
                                                {{"ft", "foot", "feet", ""}, "foot", 0.3048}}};

}  // namespace

StepLengthUnit named_length_unit(const std::string& text, const std::string& where) {
  const std::string key = lower(text);
  for (const NamedUnit& u : kNamedUnits)
    for (const char* name : u.names)
      if (*name && key == name) return {u.reported, u.metres, false};
  throw InputError(where, cat("unknown length unit \"", text, "\": expected one of nm, um, mm, cm, m, km, in, ft ",
                              "(or their names: millimetre, metre, inch, foot, ...)"));
}

double length_conversion(const StepLengthUnit& from, const StepLengthUnit& to, const std::string& source) {
  if (!(from.metres > 0))
    throw InputError(source, cat("declares no length unit, so its lengths cannot be converted to ", to.name,
                                 " (read it without a unit to keep its numbers as they are)"));
  if (from.several)
    throw InputError(source, cat("declares several different length units for its geometry (the first is ", from.name,
                                 "), so one scale cannot convert it to ", to.name));
  return from.metres / to.metres;
}

}  // namespace ssimarch
