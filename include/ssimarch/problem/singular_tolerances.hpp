// Every tolerance that decides "this point is singular" (the curve's tangent is not determined:
// the surfaces are tangent there, or branches cross), in one place, each with its unit and why it
// has its value. Measures (all dimensionless, scale-free):
//   rank ratio  sigma_min / sigma_max of J_H, Problem::rank_ratio (0 at a singular point);
//   sin(theta)  |n_F x n_G| for unit surface normals (0 where the surfaces are tangent).
// Where several of them nest, the smaller one decides that a computation is impossible and the
// larger one that a point is suspicious: 1e-14 < 1e-10 < 1e-7 < 1e-4.
#pragma once

namespace ssimarch {

/// Rank ratio at or below which Gauss-Newton has no usable update x <- x - J^+ H (the corrector
/// reports kSingular). About 100 machine epsilons: J^+ amplifies rounding by 1 / sigma_min, and
/// above this the update still carries a few correct digits.
inline constexpr double kNewtonRankRatio = 1e-14;

/// sin(theta) at or below which the tangent planes of the two surfaces count as parallel in seed
/// 000's projection corrector (Wu & Andrade, seed 000 §2): their line of intersection is then
/// not defined to more than rounding. Same reasoning as kNewtonRankRatio.
inline constexpr double kParallelPlanesSinTheta = 1e-14;

/// Rank ratio at or below which a curve jet reports kSingular (problem/curve_jet.hpp): the
/// order-k coefficients solve a system whose condition grows like 1 / rank ratio per order, so
/// below 1e-10 even the order-2 terms lose all but a few digits in double precision.
inline constexpr double kCurveJetRankTolerance = 1e-10;

/// sin(theta) below which the closed-form geometry formulas (geometry/, Ye & Maekawa 1999 §3)
/// treat the normals as parallel (default of GeometryTolerances::singular_sin_theta). About
/// sqrt(machine epsilon): near a tangential point the residual is quadratic in the distance, so a
/// point can only be located to ~1e-8 of it, where sin(theta) is of that order too.
inline constexpr double kTangentialSinTheta = 1e-7;

/// Rank ratio (and sin(theta)) below which a point is *suspected* singular: a marching end that
/// cannot take a step of min_step there stops as a singular point rather than a step underflow;
/// a start point that converged onto such a point is moved to a regular neighbour; that
/// neighbour must reach at least this ratio. 1e-4 separates a crossing of branches (the ratio
/// falls like the distance to the node) from merely high curvature by orders of magnitude at the
/// default step lengths (scale / 10 .. scale / 100).
inline constexpr double kSuspectSingularRankRatio = 1e-4;

/// Rank ratio below which a local minimum of the rank ratio along a watched march is located as a
/// possible singular point (MarchLimits::watch_crossings): at a tacnode or an oscnode the tangent
/// orientation does not reverse, but the ratio falls like the squared distance to the point
/// (A3: |grad h| ~ 2 x^2 along y = x^2), below 1e-3 for a pass within ~0.02 model units. The
/// thesis' own threshold sin(theta) < 0.01 (ch. 5 §5.2.1) fires far more often.
inline constexpr double kWatchRankRatio = 1e-3;

/// |grad f| / (reference gradient) below which an implicit surface counts as singular at a point
/// of the local curve (singular/local_curve.cpp; dimensionless). Reference: the other implicit
/// surface's gradient for an implicit-implicit pair, |Hess f| * (the problem's scale) for the
/// implicit surface of a parametric-implicit pair. At a cone's apex grad f = 0 and the surface has
/// no tangent plane: h = f / |grad f| would divide by zero, so the local curve is built over the
/// other surface and f is divided by the reference instead (the zero set is the same; only the
/// model-unit scaling of h changes). Near such a point |grad f| grows like |Hess f| times the
/// distance, so 1e-3 switches within about 1e-3 of the problem's scale of the apex, where the
/// gradient is already too small to be a faithful unit (h and its gradient blow up like
/// 1 / distance as the locator converges).
inline constexpr double kSingularSurfaceGradientRatio = 1e-3;

/// |F_u x F_v| / (|F_u|^2 + |F_v|^2) (dimensionless, at most 1/2) below which a parametric chart
/// counts as degenerate at a point: a cone's apex or a sphere's pole, inside the parameter
/// rectangle or on its edge, where F_u x F_v = 0 and the parameters are not coordinates of the
/// surface. A chart built there is valid only within about ratio * (the parameters' speed) of the
/// point, so the local curve is built over the surface's implicit form instead (when it has one;
/// singular/local_curve.cpp). 1e-3: a cone's chart at 1e-3 of its generator length from the apex,
/// or a sphere's at 1e-3 rad from its pole, still reaches the apex / pole within a few of its radii
/// of validity, and the implicit chart is exact at any distance, so the switch loses nothing.
inline constexpr double kDegenerateChartRatio = 1e-3;

/// |h| (model units, times the model size) at or below which a located critical point of the local
/// curve is a point where the surfaces meet (LocateOptions::gap_tolerance; singular/locate.hpp).
/// The corrector puts the traced points within its tolerance (default 1e-12) of both surfaces; a
/// hundred times that admits every point the tracer reached, and a near miss whose gap the
/// corrector would resolve stays out.
inline constexpr double kLocateGapTolerance = 1e-10;

/// |grad h| = sin(theta) at or below which a located point is singular
/// (LocateOptions::sine_tolerance). At a double root the location is accurate to about the square
/// root of rounding (1e-8 relative) and |grad h| grows like |Hess h| times that distance, so 1e-6
/// accepts a located node with two orders to spare, while the normals of a regular point differ
/// by more.
inline constexpr double kLocateSineTolerance = 1e-6;

/// Coefficients of the local curve h below this fraction of its largest coefficient of degree
/// >= 2 count as zero when classifying (ClassifyOptions::zero_tolerance; thesis §5.2.5's tests
/// made exact zero tests with a relative tolerance). h's coefficients carry the error of the
/// point's location (about 1e-8 relative at a double root), so smaller ones cannot be told from 0.
inline constexpr double kClassifyZeroTolerance = 1e-8;

/// The germ length as a fraction of the model size (Problem::scale()): the radius of the disc of
/// the tangent plane over which a local curve's coefficients of different degrees are weighed
/// against each other when it is classified and expanded (ClassifyOptions::length,
/// puiseux_expansion's `length`). In model units the coefficient of degree d of h scales as
/// size^(1 - d), so any comparison across degrees needs a length; one fixed in model units made
/// the same scene classify differently at every scale (Villarceau's nodes on a torus of size 0.6
/// became quadruple points, a Viviani node at size 1e-6 a contact point: the order-12 terms dwarfed
/// the quadratic ones). A tenth of the model is the automatic step (resolved_options.hpp): the
/// distance over which the march and the half-branches resolve the curve, so a term that matters
/// there is kept; at the size 10 of the seeds' scenes it is the unit length the classification
/// thresholds were judged on.
inline constexpr double kGermLengthRatio = 0.1;

/// Distance (model units, times the model size) below which two located singular points are one
/// (trace/trace_all.cpp, the registry of singular points): two locations of one node agree to
/// about 1e-8 relative, and two distinct singular points closer than 1e-7 of the model are beyond
/// what a march at any admitted step resolves.
inline constexpr double kSingularMergeDistance = 1e-7;

/// Distance (model units, times the model size) within which a point of a traced curve is on a
/// located singular point (trace/trace_all.cpp): the node's own point inserted into the curve, or
/// a march's end corrected onto it; far below the merge distance, so a curve passing near but not
/// through a node is not taken to pass through it.
inline constexpr double kOnSingularPointDistance = 1e-9;

}  // namespace ssimarch
