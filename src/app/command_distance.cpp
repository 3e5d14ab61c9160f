#include "app/command_distance.hpp"

#include <cstdio>

#include "app/command_step.hpp"
#include "app/short_number.hpp"
#include "mesh/distance.hpp"
#include "mesh/load.hpp"
#include "util/error.hpp"

namespace convray::app {
namespace {

std::string number(double value) { return short_number(value, 6); }

// "0.0123 (0.00061 of the diagonal)"
std::string length(double value, double diagonal) {
  return number(value) + " (" + number(diagonal > 0.0 ? value / diagonal : 0.0) +
         " of the diagonal)";
}

void print_side(const std::string& label, const mesh::OneSidedDistance& side, double diagonal,
                std::ostream& out) {
  out << label << " max: " << length(side.max, diagonal) << "\n"
      << label << " mean: " << length(side.mean, diagonal) << "\n"
      << label << " points: " << side.points << " (vertices and surface samples)\n";
}

}  // namespace

int run_distance(const DistanceOptions& options, std::ostream& out, std::ostream& err) {
  CommandStep step("reading " + options.a_path, kFreeMemory);
  try {
    const mesh::LoadedMesh a = mesh::load_mesh(options.a_path);
    step.now("reading " + options.b_path, kFreeMemory);
    const mesh::LoadedMesh b = mesh::load_mesh(options.b_path);
    mesh::require_triangles(a, options.a_path, "distance");
    mesh::require_triangles(b, options.b_path, "distance");
    step.now("measuring the distances", "give fewer --samples, or smaller meshes");
    const mesh::HausdorffDistance distance =
        mesh::hausdorff_distance(a.soup, b.soup, {.samples = options.samples});
    // Fractions of one length shared by every line, so they compare across lines.
    Box3 both = a.soup.bounds();
    both.extend(b.soup.bounds().lo);
    both.extend(b.soup.bounds().hi);
    const double diagonal = glm::length(both.extent());
    out << "A: " << options.a_path << " (" << a.soup.size() << " triangles)\n"
        << "B: " << options.b_path << " (" << b.soup.size() << " triangles)\n"
        << "diagonal: " << number(diagonal) << " (of the box around both)\n";
    print_side("A -> B", distance.a_to_b, diagonal, out);
    print_side("B -> A", distance.b_to_a, diagonal, out);
    out << "Hausdorff: " << length(distance.symmetric(), diagonal) << "\n"
        << "mean: " << length(distance.mean(), diagonal) << " (of the two directions' means)\n";
    return 0;
  } catch (const InputError& error) {
    err << error.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    return step.out_of_memory(err);
  } catch (const std::length_error&) {
    return step.out_of_memory(err);
  }
}

}  // namespace convray::app
