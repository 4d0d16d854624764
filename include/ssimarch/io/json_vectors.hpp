#pragma once
// A vector of doubles (Vec3, VecX, a tracer's unknowns) as a JSON array, the one form every
// writer of io/ uses for points, parameters and control points.

#include <nlohmann/json.hpp>

#include <Eigen/Core>

namespace ssimarch {

template <class Vector>
nlohmann::json vector_json(const Vector& v) {
  nlohmann::json a = nlohmann::json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) a.push_back(v[i]);
  return a;
}

}  // namespace ssimarch
