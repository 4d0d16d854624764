// Wu & Andrade's circular step as the thesis states it (thesis §4.1.2, Fig. 4.3): the centre C
// from three planes, Q_i = C + R (cos theta e1 + sin theta t), theta by the angle heuristic.
#pragma once

#include "ssimarch/march/prediction.hpp"

namespace ssimarch {

/// The centre: the intersection of the planes through P with normal tP, through Q with normal
/// tQ, and through P with normal tP x tQ (thesis §3.2 item 3, eq 3.10, geometric plane
/// assignment). False when tP and tQ are (nearly) parallel.
bool wu_andrade_centre(const Vec3& P, const Vec3& Q, const Vec3& tP, const Vec3& tQ, Vec3* centre);

/// The thesis' angle heuristic (thesis §4.1.2): theta = L if R <= 1 else L/R.
inline double wu_andrade_angle(double L, double R) { return R <= 1 ? L : L / R; }

struct WuAndradeCirclePredictor {
  static constexpr int kContactOrder = 2;
  int jet_order() const { return 1; }
  Prediction predict(const Problem& problem, const MarchState& s, double h) const;
};

}  // namespace ssimarch
