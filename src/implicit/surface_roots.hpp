#pragma once
// Finding F = T along a ray, the paper's Section 4: gather the primitives whose support the
// ray crosses, fit each one's field on its interval with a degree-6 polynomial (Eqs. 13-19),
// bound the fit's error and subdivide where it is too large, sum the fits piecewise, isolate
// the roots of each piece by Bézier clipping against the error band, and polish every root
// on the exact field.
#include <vector>

#include "implicit/convolution_surface.hpp"

namespace convray::implicit {

enum class RootMode {
  all,    // every root in [tmin, tmax]
  first,  // the first one only
  any,    // whether there is one (shadow rays): the first one, found the same way
};

void find_roots(const ConvolutionSurface::Impl& surface, const Ray& ray, double tmin, double tmax,
                RootMode mode, std::vector<double>& out, TraceStats& stats);

}  // namespace convray::implicit
