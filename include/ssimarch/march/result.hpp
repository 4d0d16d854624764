// What a trace returns: curves as polylines of points on both surfaces, why each end stopped,
// and the work it took.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "ssimarch/core/vec3.hpp"
#include "ssimarch/problem/problem.hpp"
#include "ssimarch/surface/domain.hpp"

namespace ssimarch {

/// Why one end of a traced curve stopped. Each value states its exact condition.
enum class Termination {
  kClosedLoop,     // the curve came back to its start: the start lay on the last chord (within the
                   // chord's sagitta bound) with tangents agreeing; the last point is the first one
  kLeftDomain,     // a non-periodic unknown reached its bound; the last point lies on that bound
  kSingularPoint,  // no step of length >= min_step could be taken and the curve's Jacobian is
                   // (nearly) rank deficient there: the last point is next to a singular point
  kStepUnderflow,  // no step of length >= min_step could be taken at a regular point
  kMaxPoints,      // the curve reached options.max_points points
  kMaxLength,      // the traced length reached options.max_length
  kReachedTracedCurve,  // the end came within a given distance of a curve traced before
};
std::string_view to_string(Termination t);

/// A point of a traced curve.
struct CurvePoint {
  UnknownVec x;  // the unknowns of H (params: u,v[,p,q] or x,y,z), periodic ones wrapped into the domain
  Vec3 p;  // the 3D point
  Vec3 t;  // the unit tangent in the direction of travel
};

struct TracedCurve {
  std::vector<CurvePoint> points;
  bool closed = false;
  double length = 0;  // arc length (model units), circular-arc estimate per segment
  Termination start_end = Termination::kClosedLoop;  // why the start end stopped (open curves)
  Termination end_end = Termination::kClosedLoop;
  std::string start_message, end_message;  // details, e.g. the singular point's rank ratio
  // A curve of tangential contact: the surfaces touch all along it (every point singular;
  // traced by topology/tangential_contact.hpp, not marched).
  bool tangential_contact = false;
};

/// Work counters of a trace (the thesis' Tables 4.1-4.4 report the iteration histogram).
struct TraceStats {
  long points = 0;
  long rejected_steps = 0;
  std::array<long, 5> iterations{};  // points by corrector iterations: 1, 2, 3, 4, >= 5
  long linearizations = 0;           // first-order evaluations of both surfaces
  long jet_evaluations = 0;          // higher-order (Taylor) evaluations of H
  long corrector_failures = 0;
  // Calls of the first and of the second surface (Surface::point or Surface::value, any number
  // type: an evaluation with derivatives counts once), by the tracer, its predictor and corrector.
  std::array<long, 2> surface_evaluations{};
  long predictor_fallbacks = 0;      // predictions that fell back to the tangent step (docs/marching.md)
  double time_ms = 0;
  // Wall time is `time_ms` (milliseconds, steady clock), over the whole trace() call.

  void record_iterations(int n) { ++iterations[static_cast<std::size_t>(n <= 1 ? 0 : (n >= 5 ? 4 : n - 1))]; }
  void add_surface_evaluations(const std::array<long, 2>& e) {
    surface_evaluations[0] += e[0];
    surface_evaluations[1] += e[1];
  }
  TraceStats& operator+=(const TraceStats& o);
};

/// A box of the unknowns in which the certified start-point search decided nothing: it may hold
/// a start point that was not found (docs/topology.md).
struct UncertainRegion {
  std::vector<Interval> box;  // one interval per unknown of H
  std::string system;         // the square system searched, e.g. "boundary u = 0", "turning du = 0"
  std::string reason;         // "budget spent" or "singular or non-isolated root"
};

/// How the start points were found, and what is guaranteed (docs/topology.md).
struct StartPointSearch {
  std::string method = "sampling";  // "certified", "sampling" or "given"
  bool certified = false;   // every branch in the domain has a start point (every box decided)
  long boxes = 0;           // boxes examined by the certified search
  double time_ms = 0;
  std::vector<UncertainRegion> uncertain_regions;
  std::string note;         // why sampling was used, or what the certificate does not cover
};

/// A singular point met by the trace (or hunted), as found by singular/ (docs/singular.md).
struct SingularPointReport {
  VecX x;                 // the unknowns of H
  Vec3 p = Vec3::Zero();  // the 3D point
  std::string type;       // "node", "cusp", "tacnode", ... (singular/classify.hpp)
  std::string ak;         // "A1", "D4", ...; empty where none applies
  int multiplicity = 0;
  int milnor = -1;        // -1 where infinite or beyond the local jet
  struct HalfBranch {
    Vec3 tangent = Vec3::Zero();  // unit 3D tangent leaving the point
    VecX param_tangent;           // the same in the unknowns (per unit length)
    // Leading term of the offset from the tangent line along `normal`, w = coefficient X^exponent
    // (model units; exponent 0: straight within resolution), measured before the expansion's
    // refinement: the same frame and sign as expansion[0].
    double coefficient = 0, exponent = 0;
    int continuation = -1;  // index of the half-branch that continues this one through the point
    // Puiseux expansion of the offset along `normal` (unit, 3D): w = sum coefficient X^exponent,
    // X >= 0 the distance along the tangent, up to exponent 6 (singular/puiseux.hpp).
    struct Term {
      double exponent = 0, coefficient = 0;
    };
    std::vector<Term> expansion;
    Vec3 normal = Vec3::Zero();
  };
  std::vector<HalfBranch> half_branches;
  std::vector<int> curves;  // indices of the curves through the point
};

struct TraceResult {
  std::vector<TracedCurve> curves;
  std::vector<SingularPointReport> singular_points;  // met by the curves (thesis ch. 5-6)
  std::vector<SingularPointReport> isolated_points;  // no real branch through them (hunted)
  TraceStats stats;
  StartPointSearch start_search;
  std::vector<std::string> warnings;  // e.g. a start point that could not be put on the curve
  int failed_starts = 0;              // given start points that could not be put on the curve
};

}  // namespace ssimarch
