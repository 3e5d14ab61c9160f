#pragma once
// The kernel a skeleton is convolved with. quartic: the paper's (1 - r^2/R^2)^2 with finite
// support R (implicit::ConvolutionSurface). cauchy: McCormack and Sherstyuk's
// 1 / (1 + s^2 r^2)^2 (cauchy.hpp), each primitive's field cut to zero outside its bounding box
// grown by its radius, which then is the truncation margin (implicit::CauchySurface).

namespace convray::field {

enum class KernelType { quartic, cauchy };
struct Kernel {
  KernelType type = KernelType::quartic;
  double sharpness = 1.0;  // cauchy: s (> 0); the kernel falls to 1/4 at r = 1/s
  bool operator==(const Kernel&) const = default;
};

}  // namespace convray::field
