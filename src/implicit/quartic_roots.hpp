#pragma once
// The real roots of a quartic on an interval [0, width], found without closed forms (whose
// cancellations lose digits near double roots): the Bernstein control points over a
// sub-interval change sign V times; there are at most V roots there, and exactly one when
// V = 1 (Descartes' rule of signs in Bernstein form). Intervals with V >= 2 are halved
// (de Casteljau) until every root is alone, and each is then refined in its sign-changing
// bracket by the one bracketed refiner (core/bracket_refine.hpp), to a few ulps of the root.
#include <vector>

#include "implicit/quartic.hpp"

namespace convray::implicit {

struct QuarticRootOptions {
  // Below this width (in v) an interval is not halved any more: a pair of roots closer than
  // this (the quartic barely touching zero) is told from a miss by the sign at its middle.
  double resolution = 0.0;
  bool first_only = false;  // stop after the smallest root
};

// Appends the roots of q in [0, width], ascending. Returns how many it appended.
int quartic_roots(const Quartic& q, double width, const QuarticRootOptions& options,
                  std::vector<double>& out);

}  // namespace convray::implicit
