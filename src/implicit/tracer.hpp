#pragma once
// How rays find a convolution surface:
//   fast       the window march on the summed exact field (window_march.hpp)
//   fits       the paper's per-primitive degree-6 fits and Bezier clipping (surface_roots.cpp)
//   reference  the slow exact reference tracer (reference_tracer.hpp) that the tests compare
//              both with, and `convray quick --reference` asks for
// Every root of each is polished on the exact field; only the work differs.
namespace convray::implicit {

enum class Tracer { fast, fits, reference };

}  // namespace convray::implicit
