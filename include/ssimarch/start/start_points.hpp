// Where tracing starts: solutions of H = 0 found by sampling the domain (the hunting phase,
// thesis ch. 1), given 3D points put onto the curve, and start points moved off singular points.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ssimarch/march/tracer.hpp"

namespace ssimarch {

/// Solutions of H = 0 found by Newton from a grid of samples of the domain (options.start_samples
/// per parameter direction, or per axis of the box up to 16 for implicit-implicit pairs), at
/// least half of tracer.spacing() apart. Not a guarantee of finding every component.
std::vector<VecX> find_start_points(const Tracer& tracer, TraceStats* stats);

/// The same inside `box` (one interval per unknown of H, e.g. an uncertain region of the
/// certified search) with `samples` per direction; Newton may leave the box (any solution in the
/// domain is kept).
std::vector<VecX> find_start_points_in(const Tracer& tracer, const std::vector<Interval>& box, int samples,
                                       TraceStats* stats);

/// The 3D points `points` (each near the curve) moved onto it: the unknowns nearest each point,
/// then Newton. A point that cannot be moved is left out with a warning in *warnings and counted
/// in *failed.
std::vector<VecX> start_points_near(const Tracer& tracer, const std::vector<Vec3>& points, TraceStats* stats,
                                    std::vector<std::string>* warnings, int* failed);

/// A start x that converged onto a singular point (rank ratio of J_H below
/// kSuspectSingularRankRatio and a singular point located within singular_start_radius of it,
/// start/start_tolerances.hpp; e.g. Newton from far away ending at a node) moved to a regular
/// point of the curve about half a step away, which the trace then crosses; x itself when it is
/// regular (a low rank ratio farther from the located point: 0.03 from a quadruple point), or
/// when no regular neighbour is found. Says so in *warnings (when not null) when it moves x.
VecX regular_start(const Tracer& tracer, const VecX& x, std::vector<std::string>* warnings);

}  // namespace ssimarch
