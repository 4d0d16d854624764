// Which solid each face bounds (ISO 10303-42 §5.4.4 closed_shell, §5.4.8 oriented_closed_shell,
// §4.4.x manifold_solid_brep and brep_with_voids): a solid's shells list its faces. The faces of
// one valid solid meet only along the edges and at the vertices they share, which lets
// pipeline/shared_boundary.hpp answer a pair of them from the topology.
#include "access.hpp"

namespace ssimarch::internal {

namespace {

// The faces of a CLOSED_SHELL (name, cfs_faces), or of the shell an ORIENTED_CLOSED_SHELL
// (name, *, closed_shell_element, orientation) turns.
void shell_faces(const StepAccess& a, const StepInstance& shell, std::int64_t solid,
                 std::map<std::int64_t, std::int64_t>* out) {
  const StepRecord& r = shell.records.front();
  if (shell.records.size() != 1) return;
  if (r.type == "ORIENTED_CLOSED_SHELL") {
    const StepInstance& inner = a.ref(shell, a.param(shell, r, 2, "closed_shell_element"), "closed_shell_element");
    if (&inner != &shell && inner.records.front().type == "CLOSED_SHELL") shell_faces(a, inner, solid, out);
    return;
  }
  if (r.type != "CLOSED_SHELL") return;
  for (const StepValue& f : a.list(shell, a.param(shell, r, 1, "cfs_faces"), "cfs_faces"))
    if (f.kind == StepValue::Kind::kRef) out->emplace(f.ref, solid);
}

}  // namespace

std::map<std::int64_t, std::int64_t> solids_of_faces(const StepAccess& a) {
  std::map<std::int64_t, std::int64_t> out;
  for (std::int64_t id : a.file().order) {
    const StepInstance& s = *a.file().find(id);
    const StepRecord& r = s.records.front();
    if (s.records.size() != 1 || (r.type != "MANIFOLD_SOLID_BREP" && r.type != "BREP_WITH_VOIDS")) continue;
    // A solid whose shells cannot be read gives its faces no solid: they are traced as any
    // others, and each face reports what is wrong with it when it is read.
    std::map<std::int64_t, std::int64_t> faces;
    try {
      shell_faces(a, a.ref(s, a.param(s, r, 1, "outer"), "outer"), id, &faces);
      if (r.type == "BREP_WITH_VOIDS")
        for (const StepValue& v : a.list(s, a.param(s, r, 2, "voids"), "voids"))
          shell_faces(a, a.ref(s, v, "voids"), id, &faces);
    } catch (const InputError&) {
      continue;
    }
    out.insert(faces.begin(), faces.end());
  }
  return out;
}

}  // namespace ssimarch::internal
