// Snell math: umbrella header. Header-only, C++17, depends on GLM only; no configuration
// macros (conventions are function arguments). See docs/math.md and docs/conventions.md.
#pragma once

#include "math/bounds.hpp"
#include "math/clipping.hpp"
#include "math/conventions.hpp"
#include "math/cube.hpp"
#include "math/optics.hpp"
#include "math/plane.hpp"
#include "math/projection.hpp"
#include "math/projective.hpp"
#include "math/reflection.hpp"
