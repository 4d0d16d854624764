// The placed faces of a STEP assembly (ISO 10303-44 product structure, -43 representation
// relationships; CAx-IF "Recommended Practices for AP203/AP214/AP242", assembly structure):
// a part's shape is a representation whose items hold its B-rep (MANIFOLD_SOLID_BREP, shells,
// faces); representations of the same part are joined by plain SHAPE_REPRESENTATION_RELATIONSHIPs;
// a component sits in its assembly by a REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION whose
// ITEM_DEFINED_TRANSFORMATION(item_1, item_2) maps rep_1's coordinates to rep_2's as the motion
// taking placement item_1 onto item_2, p2 = M(item_2) M(item_1)^-1 p1, or by a MAPPED_ITEM of the
// assembly's representation, p = M(mapping_target) M(mapping_origin)^-1 p_source. The component
// is the representation of the related product definition of the NEXT_ASSEMBLY_USAGE_OCCURRENCE
// that the relationship's CONTEXT_DEPENDENT_SHAPE_REPRESENTATION names (rep_1 by convention,
// rep_2 where a writer swaps them). Walking down from the representations that are no
// component, every face is listed once per path, placed by the motions composed along it.
#include <algorithm>
#include <functional>
#include <map>
#include <numeric>
#include <set>
#include <unordered_map>

#include "access.hpp"
#include "ssimarch/core/text_cat.hpp"

namespace ssimarch::internal {

namespace {

// Placed faces a model may list: a resource bound (each is a face description kept in memory,
// about 200 bytes, and a candidate of every `--faces all` pair), not a limit of the method.
constexpr std::size_t kMaxPlacedFaces = 5'000'000;

bool is_face_instance(const StepInstance& inst) { return inst.record("ADVANCED_FACE") || inst.record("FACE_SURFACE"); }

// A shape representation's record: (name, items, context_of_items), items a list, context a
// reference; the instance a SHAPE_REPRESENTATION or one of its subtypes (ADVANCED_BREP_..., a
// complex (REPRESENTATION(...) SHAPE_REPRESENTATION())). Presentation representations (styles,
// draughting) also list the solids among their items, but place nothing.
const StepRecord* representation_record(const StepInstance& inst) {
  const bool shape = std::any_of(inst.records.begin(), inst.records.end(),
                                 [](const StepRecord& r) { return r.type.ends_with("SHAPE_REPRESENTATION"); });
  if (!shape) return nullptr;
  for (const StepRecord& r : inst.records)
    if (r.type.ends_with("REPRESENTATION") && r.params.size() == 3 && r.params[1].kind == StepValue::Kind::kList &&
        r.params[2].kind == StepValue::Kind::kRef)
      return &r;
  return nullptr;
}

struct Link {
  std::int64_t parent = 0, child = 0;  // representations
  PartPlacement motion;                // child's coordinates -> parent's
  std::string name;                    // the occurrence's name
};

class Assembly {
 public:
  explicit Assembly(const StepAccess& a) : a_(a), file_(a.file()) {}

  std::vector<PlacedFace> faces() {
    scan();
    if (links_.empty()) return unplaced_faces();
    std::vector<PlacedFace> out;
    std::set<std::int64_t> children;
    for (const Link& l : links_) children.insert(find(l.child));
    // Roots: the parts no assembly places. Products' shapes first; then representations outside
    // the product structure (a SHAPE_ASPECT's, which lists the solid of a part already placed),
    // which add only the faces no product holds.
    std::vector<std::int64_t> path, roots, others;
    for (std::int64_t id : file_.order)
      if (representation_record(*file_.find(id)) && find(id) == id && !children.count(id))
        (is_product_shape(id) ? roots : others).push_back(id);
    for (std::int64_t id : roots) walk(id, PartPlacement{}, "", &path, &out);
    std::set<std::int64_t> held;
    for (const PlacedFace& f : out) held.insert(f.face);
    for (std::int64_t id : others) {
      std::vector<PlacedFace> more;
      walk(id, PartPlacement{}, "", &path, &more);
      for (PlacedFace& f : more)
        if (!held.count(f.face)) out.push_back(std::move(f));
    }
    // A part reached from no root is placed only by a cycle of placements: no place is its own.
    for (const auto& [part, reps] : members_)
      if (!visited_.count(part))
        for (std::int64_t rep : reps)
          if (!own_faces(rep).empty())
            a_.fail(*file_.find(rep),
                    "is placed only within a cycle of assembly placements (no root product places it)");
    add_faces_outside_representations(&out);
    std::map<std::int64_t, std::size_t> position;
    for (std::size_t k = 0; k < file_.order.size(); ++k) position[file_.order[k]] = k;
    std::stable_sort(out.begin(), out.end(),
                     [&](const PlacedFace& x, const PlacedFace& y) { return position[x.face] < position[y.face]; });
    // One face reached twice in the same place (two representations of one part listing the same
    // solid without a relationship between them) is one occurrence.
    out.erase(std::unique(out.begin(), out.end(),
                          [](const PlacedFace& x, const PlacedFace& y) {
                            return x.face == y.face && x.placement.rotation == y.placement.rotation &&
                                   x.placement.translation == y.placement.translation;
                          }),
              out.end());
    return out;
  }

 private:
  std::vector<PlacedFace> unplaced_faces() const {
    std::vector<PlacedFace> out;
    for (std::int64_t id : file_.order)
      if (is_face_instance(*file_.find(id))) out.push_back({id, {}, ""});
    return out;
  }

  // Representations, their plain relationships (one part: the same coordinates), then the
  // placing ones, whose component is read against the parts the plain ones made.
  void scan() {
    for (std::int64_t id : file_.order) index(*file_.find(id));
    for (bool placing : {false, true})
      for (std::int64_t id : file_.order) {
        const StepInstance& inst = *file_.find(id);
        const StepRecord* r = relationship_record(inst);
        if (r && placing == (inst.record("REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION") != nullptr))
          relationship(inst, *r);
      }
    for (const auto& [parent, item] : mapped_) mapped_item(parent, *item);
    for (const auto& [rep, root] : parent_) members_[find(rep)].push_back(rep);
    for (const Link& l : links_) components_[find(l.parent)].push_back(&l);
    for (const auto& [definition, reps] : shapes_)
      if (const StepInstance* pd = file_.find(definition); pd && pd->record("PRODUCT_DEFINITION"))
        for (std::int64_t rep : reps)
          if (parent_.count(rep)) product_parts_.insert(find(rep));
  }

  // The instances the walk looks up: representations with their MAPPED_ITEMs, the
  // CONTEXT_DEPENDENT_SHAPE_REPRESENTATION of each relationship, the shapes of each definition.
  void index(const StepInstance& inst) {
    if (const StepRecord* r = representation_record(inst)) {
      parent_[inst.id] = inst.id;
      for (const StepValue& item : r->params[1].items)
        if (item.kind == StepValue::Kind::kRef)
          if (const StepInstance* m = file_.find(item.ref); m && m->record("MAPPED_ITEM"))
            mapped_.push_back({inst.id, m});
    }
    if (const StepRecord* c = inst.record("CONTEXT_DEPENDENT_SHAPE_REPRESENTATION");
        c && c->params.size() == 2 && c->params[0].kind == StepValue::Kind::kRef)
      cdsr_[c->params[0].ref] = &inst;
    const StepRecord* sdr = inst.record("SHAPE_DEFINITION_REPRESENTATION");
    if (!sdr || sdr->params.size() != 2 || sdr->params[0].kind != StepValue::Kind::kRef ||
        sdr->params[1].kind != StepValue::Kind::kRef)
      return;
    const StepInstance* pds = file_.find(sdr->params[0].ref);
    const StepRecord* pr = pds ? pds->record("PRODUCT_DEFINITION_SHAPE") : nullptr;
    if (pr && pr->params.size() >= 3 && pr->params[2].kind == StepValue::Kind::kRef)
      shapes_[pr->params[2].ref].push_back(sdr->params[1].ref);
  }

  static const StepRecord* relationship_record(const StepInstance& inst) {
    for (const char* type : {"REPRESENTATION_RELATIONSHIP", "SHAPE_REPRESENTATION_RELATIONSHIP"})
      if (const StepRecord* r = inst.record(type); r && r->params.size() == 4) return r;
    return nullptr;
  }

  void relationship(const StepInstance& inst, const StepRecord& r) {
    const std::int64_t rep1 = a_.ref(inst, r.params[2], "rep_1").id, rep2 = a_.ref(inst, r.params[3], "rep_2").id;
    if (!parent_.count(rep1) || !parent_.count(rep2)) return;  // not between shapes
    const StepRecord* with = inst.record("REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION");
    if (!with) {
      unite(rep1, rep2);
      return;
    }
    const StepInstance& t =
        a_.ref(inst, a_.param(inst, *with, 0, "transformation_operator"), "transformation_operator");
    if (!t.record("ITEM_DEFINED_TRANSFORMATION"))
      a_.fail(t,
              "is not an ITEM_DEFINED_TRANSFORMATION, the one placement of a component that is read (a "
              "CARTESIAN_TRANSFORMATION_OPERATOR_3D, scaled or mirrored, is not read yet)");
    const StepRecord& tr = a_.record(t, "ITEM_DEFINED_TRANSFORMATION");
    const PartPlacement from =
        placement_motion(a_, a_.ref(t, a_.param(t, tr, 2, "transform_item_1"), "transform_item_1"));
    const PartPlacement to =
        placement_motion(a_, a_.ref(t, a_.param(t, tr, 3, "transform_item_2"), "transform_item_2"));
    Link l{rep2, rep1, from.inverse().then(to), occurrence_name(inst)};
    if (component_is(inst, rep2) && !component_is(inst, rep1)) l = {rep1, rep2, l.motion.inverse(), l.name};
    links_.push_back(std::move(l));
  }

  void mapped_item(std::int64_t parent, const StepInstance& m) {
    const StepRecord& r = a_.record(m, "MAPPED_ITEM");
    const StepInstance& map = a_.ref(m, a_.param(m, r, 1, "mapping_source"), "mapping_source");
    const StepRecord& mr = a_.record(map, "REPRESENTATION_MAP");
    const PartPlacement origin =
        placement_motion(a_, a_.ref(map, a_.param(map, mr, 0, "mapping_origin"), "mapping_origin"));
    const std::int64_t child = a_.ref(map, a_.param(map, mr, 1, "mapped_representation"), "mapped_representation").id;
    if (!parent_.count(child)) a_.fail(map, "mapped_representation must be a representation");
    const PartPlacement target = placement_motion(a_, a_.ref(m, a_.param(m, r, 2, "mapping_target"), "mapping_target"));
    const std::string& name = r.params[0].text;
    links_.push_back({parent, child, origin.inverse().then(target), name.empty() ? cat("#", m.id) : name});
  }

  // The CONTEXT_DEPENDENT_SHAPE_REPRESENTATION of a relationship and its occurrence.
  const StepInstance* occurrence(const StepInstance& relationship) const {
    const auto it = cdsr_.find(relationship.id);
    if (it == cdsr_.end()) return nullptr;
    const StepRecord& r = a_.record(*it->second, "CONTEXT_DEPENDENT_SHAPE_REPRESENTATION");
    const StepInstance& pds = a_.ref(*it->second, r.params[1], "represented_product_relation");
    const StepRecord* pr = pds.record("PRODUCT_DEFINITION_SHAPE");
    if (!pr || pr->params.size() < 3 || pr->params[2].kind != StepValue::Kind::kRef) return nullptr;
    const StepInstance* nauo = file_.find(pr->params[2].ref);
    return nauo && nauo->record("NEXT_ASSEMBLY_USAGE_OCCURRENCE") ? nauo : nullptr;
  }

  std::string occurrence_name(const StepInstance& relationship) {
    const StepInstance* nauo = occurrence(relationship);
    if (!nauo) return cat("#", relationship.id);
    const StepRecord& r = a_.record(*nauo, "NEXT_ASSEMBLY_USAGE_OCCURRENCE");
    for (std::size_t k : {std::size_t{1}, std::size_t{0}})
      if (k < r.params.size() && r.params[k].kind == StepValue::Kind::kString && !r.params[k].text.empty())
        return r.params[k].text;
    return cat("#", nauo->id);
  }

  // Whether `rep` is (a representation of the same part as) the shape of the component that the
  // relationship's occurrence places: SHAPE_DEFINITION_REPRESENTATION -> PRODUCT_DEFINITION_SHAPE
  // -> the occurrence's related product definition.
  bool component_is(const StepInstance& relationship, std::int64_t rep) {
    const StepInstance* nauo = occurrence(relationship);
    if (!nauo) return false;
    const StepRecord& n = a_.record(*nauo, "NEXT_ASSEMBLY_USAGE_OCCURRENCE");
    if (n.params.size() < 5 || n.params[4].kind != StepValue::Kind::kRef) return false;
    for (std::int64_t shape : shapes_of(n.params[4].ref))
      if (find(shape) == find(rep)) return true;
    return false;
  }

  // Whether a part's representations include a product's shape (SHAPE_DEFINITION_REPRESENTATION
  // of a PRODUCT_DEFINITION_SHAPE of a PRODUCT_DEFINITION).
  bool is_product_shape(std::int64_t part) const { return product_parts_.count(part) > 0; }

  const std::vector<std::int64_t>& shapes_of(std::int64_t product_definition) const {
    static const std::vector<std::int64_t> kNone;
    const auto it = shapes_.find(product_definition);
    return it == shapes_.end() ? kNone : it->second;
  }

  std::int64_t find(std::int64_t x) {
    while (parent_.at(x) != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(std::int64_t x, std::int64_t y) { parent_[find(x)] = find(y); }

  // The faces a representation's items hold (shells and solids down to their faces; a MAPPED_ITEM
  // is a placed component, not a face of this one).
  const std::vector<std::int64_t>& own_faces(std::int64_t rep) {
    if (const auto it = faces_of_.find(rep); it != faces_of_.end()) return it->second;
    std::vector<std::int64_t> found;
    std::set<std::int64_t> seen;
    std::vector<std::int64_t> todo;
    std::function<void(const StepValue&)> refs = [&](const StepValue& v) {
      if (v.kind == StepValue::Kind::kRef) todo.push_back(v.ref);
      for (const StepValue& x : v.items) refs(x);
    };
    refs(representation_record(*file_.find(rep))->params[1]);  // the items
    while (!todo.empty()) {
      const std::int64_t id = todo.back();
      todo.pop_back();
      const StepInstance* inst = file_.find(id);
      if (!inst || !seen.insert(id).second || inst->record("MAPPED_ITEM") || representation_record(*inst)) continue;
      if (is_face_instance(*inst)) {
        found.push_back(id);
        continue;
      }
      for (const StepRecord& r : inst->records)
        for (const StepValue& v : r.params) refs(v);
    }
    all_reached_.insert(found.begin(), found.end());
    return faces_of_[rep] = std::move(found);
  }

  void walk(std::int64_t part, const PartPlacement& motion, const std::string& name, std::vector<std::int64_t>* path,
            std::vector<PlacedFace>* out) {
    if (std::find(path->begin(), path->end(), part) != path->end())
      a_.fail(*file_.find(part), "is its own component: the assembly's placements form a cycle");
    path->push_back(part);
    visited_.insert(part);
    for (std::int64_t rep : members_[part])
      for (std::int64_t f : own_faces(rep)) {
        out->push_back({f, motion, name});
        if (out->size() > kMaxPlacedFaces)
          throw InputError(file_.source, cat("the assembly places more than ", kMaxPlacedFaces, " faces"));
      }
    for (const Link* l : components_[part])
      walk(find(l->child), l->motion.then(motion), name.empty() ? l->name : name + "/" + l->name, path, out);
    path->pop_back();
  }

  void add_faces_outside_representations(std::vector<PlacedFace>* out) {
    for (std::int64_t id : file_.order)
      if (is_face_instance(*file_.find(id)) && !all_reached_.count(id)) out->push_back({id, {}, ""});
  }

  const StepAccess& a_;
  const StepFile& file_;
  std::map<std::int64_t, std::int64_t> parent_;  // representations, union-find of one part's
  std::vector<std::pair<std::int64_t, const StepInstance*>> mapped_;
  std::vector<Link> links_;
  std::map<std::int64_t, std::vector<std::int64_t>> members_;    // a part's representations
  std::map<std::int64_t, std::vector<const Link*>> components_;  // a part's placed components
  std::unordered_map<std::int64_t, const StepInstance*> cdsr_;
  std::unordered_map<std::int64_t, std::vector<std::int64_t>> shapes_;  // by product definition
  std::set<std::int64_t> product_parts_;                                // parts that are a product's shape
  std::unordered_map<std::int64_t, std::vector<std::int64_t>> faces_of_;
  std::set<std::int64_t> all_reached_;
  std::set<std::int64_t> visited_;  // parts walked
};

}  // namespace

std::vector<PlacedFace> placed_faces(const StepAccess& a) { return Assembly(a).faces(); }

}  // namespace ssimarch::internal
