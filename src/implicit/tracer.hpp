#pragma once
// How rays find a convolution surface: the fast path (fits, Bezier clipping, exact polish), or
// the slow exact reference tracer (reference_tracer.hpp) that the tests compare it with and
// `convray quick --reference` asks for.
namespace convray::implicit {

enum class Tracer { fast, reference };

}  // namespace convray::implicit
