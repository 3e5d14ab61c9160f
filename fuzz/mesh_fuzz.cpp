// libFuzzer target for the mesh readers (src/mesh/load.hpp).
//
// One binary per format, chosen at build time by CONVRAY_FUZZ_FORMAT (fuzz/CMakeLists.txt),
// so that each format gets its own run and corpus:
//   obj, ply, stl, off  the input is the file;
//   gz                  the first byte picks the format inside (obj, ply, stl, off), the rest is
//                       the gzip file;
//   any                 the first byte picks one of the eight (four formats, plain or gzip).
// Only InputError may come out of the loader: anything else escaping, a crash, a sanitizer
// report, a leak, a timeout or an out-of-memory is a bug the fuzzer reports.
//
// Built with CONVRAY_FUZZ_WRITE_SEEDS instead, this file is `mesh_fuzz_seeds DIR`: it writes
// a starting corpus for every target, from our own writers and procedural meshes.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "mesh/load.hpp"
#include "mesh/skeleton_stats.hpp"
#include "util/error.hpp"

namespace {

const char* const kInnerExtensions[] = {".obj", ".ply", ".stl", ".off"};

// The file name the loader sees (it picks the format), and the bytes that remain.
std::string name_for(std::string_view format, std::string_view& bytes) {
  if (format != "gz" && format != "any") return "fuzz." + std::string(format);
  if (bytes.empty()) return "";
  unsigned selector = static_cast<unsigned char>(bytes.front());
  bytes.remove_prefix(1);
  std::string name = std::string("fuzz") + kInnerExtensions[selector % 4];
  bool gzip = format == "gz" || (selector / 4) % 2 == 1;
  return gzip ? name + ".gz" : name;
}

}  // namespace

#ifndef CONVRAY_FUZZ_WRITE_SEEDS

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string_view bytes(reinterpret_cast<const char*>(data), size);
  std::string name = name_for(CONVRAY_FUZZ_FORMAT, bytes);
  if (name.empty()) return 0;
  try {
    convray::mesh::LoadedMesh mesh = convray::mesh::load_mesh_from_memory(bytes, name);
    convray::mesh::compute_stats(mesh.soup);  // whatever loads must be safe to analyse
    convray::mesh::compute_skeleton_stats(mesh);  // bounds, segment lengths, point spacing
  } catch (const convray::InputError&) {
    // The expected outcome for almost every input.
  }
  return 0;
}

#else  // the seed writer

#include <zlib.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "fixtures/defective_soups.hpp"
#include "mesh/procedural.hpp"
#include "mesh/write.hpp"

namespace {

namespace fs = std::filesystem;
using convray::mesh::MeshEncoding;
using convray::mesh::TriangleSoup;

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

void write_file(const fs::path& path, std::string_view bytes) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::string gzip(std::string_view bytes) {
  uLongf size = compressBound(static_cast<uLong>(bytes.size())) + 32;
  std::string out(size, '\0');
  z_stream stream{};
  deflateInit2(&stream, Z_BEST_COMPRESSION, Z_DEFLATED, 16 + MAX_WBITS, 8, Z_DEFAULT_STRATEGY);
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  stream.avail_in = static_cast<uInt>(bytes.size());
  stream.next_out = reinterpret_cast<Bytef*>(out.data());
  stream.avail_out = static_cast<uInt>(out.size());
  deflate(&stream, Z_FINISH);
  out.resize(stream.total_out);
  deflateEnd(&stream);
  return out;
}

struct Sample {
  std::string file_name;  // its extension is the format
  std::string bytes;
};

std::vector<Sample> samples(const fs::path& scratch) {
  std::vector<std::pair<std::string, TriangleSoup>> soups = {
      {"icosahedron", convray::mesh::icosphere(convray::Vec3(0.0), 1.0, 0)},
      {"sphere", convray::mesh::icosphere(convray::Vec3(1, 2, 3), 0.5, 1)},
      {"torus", convray::mesh::torus(2.0, 0.5, 6, 4)},
      {"soup", convray::mesh::defective_soup({.subdivisions = 1, .zero_area = true, .repeated_vertex = true})},
  };
  const std::vector<std::pair<std::string, MeshEncoding>> encodings = {
      {".obj", MeshEncoding::Default}, {".off", MeshEncoding::Default}, {".ply", MeshEncoding::Ascii},
      {".ply", MeshEncoding::Binary},  {".stl", MeshEncoding::Ascii},   {".stl", MeshEncoding::Binary}};
  std::vector<Sample> result;
  for (const auto& [name, soup] : soups) {
    for (const auto& [extension, encoding] : encodings) {
      fs::path path = scratch / (name + extension);
      convray::mesh::save_mesh(soup, path.string(), encoding);
      std::string tag = encoding == MeshEncoding::Binary ? "-binary" : (encoding == MeshEncoding::Ascii ? "-ascii" : "");
      result.push_back({name + tag + extension, read_file(path)});
    }
  }
  // Formats our writers do not produce: polygons, and a PLY with more elements.
  result.push_back({"polygons.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 2 0\nvt 0 0\nvn 0 0 1\n"
                                    "g quad\nf 1/1/1 2/1/1 3/1/1 4/1/1\no roof\nf -2 -3 -1\n"});
  result.push_back({"polygons.off", "COFF\n# a house\n5 2 0\n0 0 0 1 0 0 1\n1 0 0 1 0 0 1\n1 1 0 0 1 0 1\n"
                                    "0 1 0 0 1 0 1\n0.5 2 0 0 0 1 1\n4 0 1 2 3\n3 3 2 4\n"});
  result.push_back({"extras.ply", "ply\nformat ascii 1.0\ncomment extras\nelement vertex 4\nproperty float x\n"
                                  "property float y\nproperty float z\nproperty uchar red\nelement face 2\n"
                                  "property list uchar int vertex_indices\nproperty int flags\nelement edge 1\n"
                                  "property int vertex1\nproperty int vertex2\nend_header\n0 0 0 255\n1 0 0 0\n"
                                  "1 1 0 9\n0 1 0 7\n3 0 1 2 0\n4 0 2 3 1 1\n0 1\n"});
  return result;
}

}  // namespace

// mesh_fuzz_seeds DIR: writes DIR/<target>/<sample> for the targets obj, ply, stl, off, gz, any.
int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s DIRECTORY\n", argv[0]);
    return 2;
  }
  fs::path root = argv[1];
  fs::path scratch = root / ".scratch";
  fs::create_directories(scratch);
  for (const Sample& sample : samples(scratch)) {
    std::string extension = fs::path(sample.file_name).extension().string().substr(1);
    unsigned inner = 0;
    while (std::string(kInnerExtensions[inner]) != "." + extension) ++inner;
    write_file(root / extension / sample.file_name, sample.bytes);
    std::string compressed = gzip(sample.bytes);
    write_file(root / "gz" / (sample.file_name + ".gz"), std::string(1, static_cast<char>(inner)) + compressed);
    write_file(root / "any" / sample.file_name, std::string(1, static_cast<char>(inner)) + sample.bytes);
    write_file(root / "any" / (sample.file_name + ".gz"), std::string(1, static_cast<char>(inner + 4)) + compressed);
  }
  fs::remove_all(scratch);
  return 0;
}

#endif
