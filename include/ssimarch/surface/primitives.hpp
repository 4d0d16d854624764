// All primitives (each has both a parametric and an implicit form).
#pragma once

#include "ssimarch/surface/capsule.hpp"
#include "ssimarch/surface/cone.hpp"
#include "ssimarch/surface/cylinder.hpp"
#include "ssimarch/surface/ellipsoid.hpp"
#include "ssimarch/surface/paraboloid.hpp"
#include "ssimarch/surface/plane.hpp"
#include "ssimarch/surface/sphere.hpp"
#include "ssimarch/surface/torus.hpp"
