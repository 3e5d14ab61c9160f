// The polygonizer evaluation of docs/polygonization-libraries.md: the convolution surface
// F = T of a soup meshed by CGAL (Mesh_3), OpenVDB (volumeToMesh) and a hand-written dual
// contouring, each output measured the same way (topology, self intersections, accuracy on
// the exact field, triangle shape); `--ours FILE` measures a mesh made elsewhere, and
// `--soup-distance` meshes OpenVDB's unsigned distance of the soup at the offset instead.
//
//   polygonizer_libraries (MESH | --procedural defective|sheet) --radius R --offset D
//       --cell H [--fit-box S] [--method cgal|openvdb|dc|all] [--adaptivity A]
//       [--ours FILE] [--soup-distance] [--threads N] [--write-prefix PATH]
//
// Prints one Markdown table row per output, then a note per method (parameters, what ran
// in parallel). Built only when CGAL and OpenVDB are both found (bench/CMakeLists.txt).
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "fixtures/defective_soups.hpp"
#include "field/threshold.hpp"
#include "mesh/load.hpp"
#include "mesh/procedural.hpp"
#include "mesh/write.hpp"
#include "polygonizer_eval.hpp"

namespace {

using namespace convray;

struct Options {
  std::string mesh, procedural, method = "all", ours, write_prefix;
  double radius = 2.0, offset = 1.0, cell = 1.0, fit_box = 0.0, adaptivity = 0.2;
  bool soup_distance = false;
  int threads = 2;
};

constexpr const char* kUsage =
    "usage: polygonizer_libraries (MESH | --procedural defective|sheet) --radius R --offset D\n"
    "         --cell H [--fit-box S] [--method cgal|openvdb|dc|all] [--adaptivity A]\n"
    "         [--ours FILE] [--soup-distance] [--threads N] [--write-prefix PATH]\n";

[[noreturn]] void usage_error(const std::string& message) {
  std::fprintf(stderr, "polygonizer_libraries: %s\n%s", message.c_str(), kUsage);
  std::exit(2);
}

double number(const std::string& text, const std::string& what) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0') usage_error(what + ": expected a number, got '" + text + "'");
  return value;
}

Options parse_options(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--soup-distance") {
      o.soup_distance = true;
      continue;
    }
    if (arg.rfind("--", 0) != 0) {
      o.mesh = arg;
      continue;
    }
    if (i + 1 >= argc) usage_error(arg + " needs a value");
    const std::string value = argv[++i];
    if (arg == "--procedural")
      o.procedural = value;
    else if (arg == "--radius")
      o.radius = number(value, arg);
    else if (arg == "--offset")
      o.offset = number(value, arg);
    else if (arg == "--cell")
      o.cell = number(value, arg);
    else if (arg == "--fit-box")
      o.fit_box = number(value, arg);
    else if (arg == "--adaptivity")
      o.adaptivity = number(value, arg);
    else if (arg == "--method")
      o.method = value;
    else if (arg == "--ours")
      o.ours = value;
    else if (arg == "--threads")
      o.threads = static_cast<int>(number(value, arg));
    else if (arg == "--write-prefix")
      o.write_prefix = value;
    else
      usage_error("unknown option " + arg);
  }
  if (o.mesh.empty() == o.procedural.empty()) usage_error("give one MESH or --procedural");
  if (!(o.radius > 0 && o.offset >= 0 && o.offset < o.radius && o.cell > 0)) {
    usage_error("need R > 0, 0 <= D < R, H > 0");
  }
  const std::vector<std::string> methods = {"cgal", "openvdb", "dc", "all", "none"};
  if (std::find(methods.begin(), methods.end(), o.method) == methods.end()) {
    usage_error("--method: cgal, openvdb, dc, all or none");
  }
  return o;
}

mesh::TriangleSoup load_soup(const Options& o) {
  mesh::TriangleSoup soup;
  if (o.procedural == "defective")
    soup = mesh::defective_soup();
  else if (o.procedural == "sheet")
    soup = mesh::sheet_with_hole(1.0, 8, 0.4);
  else if (!o.procedural.empty())
    usage_error("--procedural: defective or sheet");
  else
    soup = mesh::load_mesh(o.mesh).soup;
  // As `convray quick --fit-box` (the paper's Table 1): largest extent = S, box centred.
  if (o.fit_box > 0) mesh::fit_into_box(soup, o.fit_box);
  // The input as measured, so `convray polygonize` can be run on exactly it (for --ours).
  if (!o.write_prefix.empty()) mesh::save_mesh(soup, o.write_prefix + "input.obj");
  return soup;
}

void print_header() {
  std::printf(
      "| method | time s | triangles | vertices | boundary e. | non-manifold e. | "
      "inconsistent e. | components | Euler | self-int. pairs | max abs(F-T)/T | "
      "mean abs(F-T)/T | min angle | share < 10 deg | max centroid dist. | "
      "mean centroid dist. | unprojected | outward | max abs(dist-D) | mean abs(dist-D) |\n");
  std::printf("|---|");
  for (int column = 1; column < 20; ++column) std::printf("---:|");
  std::printf("\n");
}

void print_row(const std::string& name, double seconds, const bench::Quality& q) {
  std::printf(
      "| %s | %.2f | %zu | %zu | %zu | %zu | %zu | %zu | %ld | %zu | %.2e | %.2e | %.2f | %.2f%% "
      "| %.3g | %.3g | %zu | %.2f%% | %.3g | %.3g |\n",
      name.c_str(), seconds, q.triangles, q.vertices, q.boundary_edges, q.non_manifold_edges,
      q.inconsistent_edges, q.components, q.euler, q.self_intersecting_pairs, q.max_field_error,
      q.mean_field_error, q.min_angle_degrees, 100.0 * q.small_angle_fraction,
      q.max_centroid_distance, q.mean_centroid_distance, q.unprojected_centroids,
      100.0 * q.outward_fraction, q.max_offset_error, q.mean_offset_error);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse_options(argc, argv);
  // Every parallel part (our sampling and measures, OpenVDB, CGAL's Parallel_tag) runs on
  // TBB: this caps them all alike.
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, o.threads);
  try {
    const mesh::TriangleSoup soup = load_soup(o);
    std::vector<field::Triangle> triangles;
    for (size_t t = 0; t < soup.triangles.size(); ++t) {
      const auto c = soup.corners(t);
      triangles.push_back({c[0], c[1], c[2]});
    }
    const auto build_start = std::chrono::steady_clock::now();
    const implicit::MeshField field(std::move(triangles), o.radius);
    const double build_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - build_start).count();
    bench::Problem problem;
    problem.field = &field;
    problem.threshold = field::threshold_for_offset(1.0, o.radius, o.offset);
    problem.offset = o.offset;
    problem.cell = o.cell;
    problem.soup_bounds = soup.bounds();
    problem.soup = &soup;
    std::printf(
        "input: %s, %zu triangles; R %g, offset %g (T %.6g), cell %g; field build %.2f s; "
        "%d threads\n\n",
        o.procedural.empty() ? o.mesh.c_str() : o.procedural.c_str(), soup.size(), o.radius,
        o.offset, problem.threshold, o.cell, build_seconds, o.threads);
    print_header();

    std::vector<std::string> notes;
    auto report = [&](const std::string& name, const bench::PolygonizerOutput& out) {
      print_row(name, out.seconds, bench::measure_quality(problem, out.mesh));
      notes.push_back(name + ": " + out.note);
      if (!o.write_prefix.empty()) mesh::save_mesh(out.mesh, o.write_prefix + name + ".ply");
    };
    const bool all = o.method == "all";
    if (all || o.method == "cgal") report("cgal", bench::polygonize_cgal(problem));
    if (all || o.method == "openvdb") {
      report("openvdb-a0", bench::polygonize_openvdb(problem, 0.0));
      const std::string name = "openvdb-a" + std::to_string(o.adaptivity).substr(0, 4);
      report(name, bench::polygonize_openvdb(problem, o.adaptivity));
    }
    if (all || o.method == "dc") report("dc", bench::polygonize_dual_contouring(problem));
    if (o.soup_distance) report("openvdb-udf", bench::openvdb_soup_offset(problem, o.offset));
    if (!o.ours.empty()) {
      bench::PolygonizerOutput ours;
      ours.mesh = mesh::load_mesh(o.ours).soup;
      ours.note = "mesh read from " + o.ours + " (time not measured here)";
      report("ours", ours);
    }
    std::printf("\n");
    for (const std::string& note : notes) std::printf("- %s\n", note.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "polygonizer_libraries: %s\n", e.what());
    return 1;
  }
  return 0;
}
