#include "ssimarch/pipeline/scene.hpp"

#include "ssimarch/core/error.hpp"
#include "ssimarch/core/text_cat.hpp"

namespace ssimarch {

const Surface& Scene::surface(const std::string& name) const {
  auto it = surfaces.find(name);
  if (it == surfaces.end())
    throw InputError(
        source, "unknown surface \"" + name + "\" (the scene defines: " + internal::join_names(surface_names) + ")");
  return it->second;
}

const IntersectionSpec* Scene::intersection(const std::string& name) const {
  for (const auto& s : intersections)
    if (s.name == name) return &s;
  return nullptr;
}

std::string Scene::intersection_names() const {
  std::vector<std::string> names;
  for (const auto& s : intersections) names.push_back(s.name);
  return internal::join_names(names);
}

Problem Scene::problem(const IntersectionSpec& spec) const {
  const Surface& a = surface(spec.surfaces[0]);
  const Surface& b = surface(spec.surfaces[1]);
  return spec.swapped ? Problem(b, a, spec.kind) : Problem(a, b, spec.kind);
}

PairKind choose_pair_kind(const Surface& a, const Surface& b, const std::optional<std::array<SurfaceForm, 2>>& as,
                          const std::string& where, bool* swapped) {
  *swapped = false;
  if (as) {
    const Surface* s[2] = {&a, &b};
    for (std::size_t i = 0; i < 2; ++i) {
      const std::string w = where + ".as[" + std::to_string(i) + "]";
      if ((*as)[i] == SurfaceForm::kParametric && !s[i]->is_parametric())
        throw InputError(w, "this " + std::string(s[i]->type_name()) + " surface has no parametric form");
      if ((*as)[i] == SurfaceForm::kImplicit && !s[i]->is_implicit())
        throw InputError(w, "this " + std::string(s[i]->type_name()) + " surface has no implicit form");
    }
    if ((*as)[0] == (*as)[1])
      return (*as)[0] == SurfaceForm::kParametric ? PairKind::kParametricParametric : PairKind::kImplicitImplicit;
    *swapped = (*as)[0] == SurfaceForm::kImplicit;
    return PairKind::kParametricImplicit;
  }
  if (a.is_implicit() && b.is_implicit()) return PairKind::kImplicitImplicit;
  if (b.is_implicit() && a.is_parametric()) return PairKind::kParametricImplicit;
  if (a.is_implicit() && b.is_parametric()) {
    *swapped = true;
    return PairKind::kParametricImplicit;
  }
  if (a.is_parametric() && b.is_parametric()) return PairKind::kParametricParametric;
  throw InputError(where, "these two surfaces cannot be intersected: one is implicit only and the other has no form to pair with it");
}

}  // namespace ssimarch
