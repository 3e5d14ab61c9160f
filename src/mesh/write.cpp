#include "mesh/write.hpp"

#include <cerrno>
#include <cstdint>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string_view>

#include "mesh/format.hpp"
#include "mesh/load_error.hpp"
#include "util/atomic_file.hpp"

namespace convray::mesh {
namespace {

// Collects output in memory and hands it to the atomic file in large pieces.
class Output {
 public:
  explicit Output(AtomicFile& file) : file_(file) {}

  void text(std::string_view s) {
    buffer_.append(s);
    flush_if_full();
  }
  void number(double value) {
    char digits[32];
    auto [end, ec] = std::to_chars(digits, digits + sizeof digits, value);  // shortest exact
    buffer_.append(digits, end);
  }
  void integer(uint64_t value) {
    char digits[24];
    auto [end, ec] = std::to_chars(digits, digits + sizeof digits, value);
    buffer_.append(digits, end);
  }
  template <typename T>
  void little_endian(T value) {
    static_assert(std::endian::native == std::endian::little, "binary writers assume a little-endian host");
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    buffer_.append(bytes, sizeof(T));
    flush_if_full();
  }
  void finish() { flush(); }

 private:
  void flush_if_full() {
    if (buffer_.size() >= (size_t{1} << 20)) flush();
  }
  void flush() {
    if (!buffer_.empty()) file_.write(buffer_);
    buffer_.clear();
  }

  AtomicFile& file_;
  std::string buffer_;
};

void write_point(Output& out, const Vec3& p) {
  out.number(p.x);
  out.text(" ");
  out.number(p.y);
  out.text(" ");
  out.number(p.z);
}

void write_obj(const TriangleSoup& soup, const std::vector<Vec3>* normals, Output& out) {
  out.text("# convray triangle soup\n");
  for (const Vec3& p : soup.vertices) {
    out.text("v ");
    write_point(out, p);
    out.text("\n");
  }
  if (normals) {
    for (const Vec3& n : *normals) {
      out.text("vn ");
      write_point(out, n);
      out.text("\n");
    }
  }
  for (const Triangle& t : soup.triangles) {
    out.text("f");
    for (uint32_t index : t) {
      out.text(" ");
      out.integer(uint64_t{index} + 1);  // OBJ counts from 1
      if (normals) {
        out.text("//");  // vertex//normal: the normal with the vertex's own number
        out.integer(uint64_t{index} + 1);
      }
    }
    out.text("\n");
  }
}

void write_off(const TriangleSoup& soup, Output& out) {
  out.text("OFF\n");
  out.integer(soup.vertices.size());
  out.text(" ");
  out.integer(soup.triangles.size());
  out.text(" 0\n");
  for (const Vec3& p : soup.vertices) {
    write_point(out, p);
    out.text("\n");
  }
  for (const Triangle& t : soup.triangles) {
    out.text("3");
    for (uint32_t index : t) {
      out.text(" ");
      out.integer(index);
    }
    out.text("\n");
  }
}

void write_ply(const TriangleSoup& soup, const std::vector<Vec3>* normals, Output& out,
               bool binary) {
  out.text("ply\n");
  out.text(binary ? "format binary_little_endian 1.0\n" : "format ascii 1.0\n");
  out.text("comment convray triangle soup\nelement vertex ");
  out.integer(soup.vertices.size());
  out.text("\nproperty double x\nproperty double y\nproperty double z\n");
  if (normals) out.text("property double nx\nproperty double ny\nproperty double nz\n");
  out.text("element face ");
  out.integer(soup.triangles.size());
  out.text("\nproperty list uchar uint vertex_indices\nend_header\n");
  for (size_t v = 0; v < soup.vertices.size(); ++v) {
    const Vec3& p = soup.vertices[v];
    if (binary) {
      for (int axis = 0; axis < 3; ++axis) out.little_endian(p[axis]);
      if (normals) {
        for (int axis = 0; axis < 3; ++axis) out.little_endian((*normals)[v][axis]);
      }
    } else {
      write_point(out, p);
      if (normals) {
        out.text(" ");
        write_point(out, (*normals)[v]);
      }
      out.text("\n");
    }
  }
  for (const Triangle& t : soup.triangles) {
    if (binary) {
      out.little_endian(uint8_t{3});
      for (uint32_t index : t) out.little_endian(index);
    } else {
      out.text("3");
      for (uint32_t index : t) {
        out.text(" ");
        out.integer(index);
      }
      out.text("\n");
    }
  }
}

// Unit normal of the triangle (zero when it has no area): STL insists on one.
Vec3 facet_normal(const std::array<Vec3, 3>& corners) {
  Vec3 normal = glm::cross(corners[1] - corners[0], corners[2] - corners[0]);
  double length = glm::length(normal);
  return length > 0.0 && std::isfinite(length) ? normal / length : Vec3(0.0);
}

void write_stl_ascii(const TriangleSoup& soup, Output& out) {
  out.text("solid convray\n");
  for (size_t t = 0; t < soup.size(); ++t) {
    std::array<Vec3, 3> corners = soup.corners(t);
    out.text(" facet normal ");
    write_point(out, facet_normal(corners));
    out.text("\n  outer loop\n");
    for (const Vec3& p : corners) {
      out.text("   vertex ");
      write_point(out, p);
      out.text("\n");
    }
    out.text("  endloop\n endfacet\n");
  }
  out.text("endsolid convray\n");
}

void write_stl_binary(const TriangleSoup& soup, Output& out) {
  // The 80-byte header must not start with "solid", or readers may take the file for text.
  char header[80];
  std::memset(header, ' ', sizeof header);
  std::string_view title = "binary STL, convray triangle soup";
  std::memcpy(header, title.data(), title.size());
  out.text(std::string_view(header, sizeof header));
  out.little_endian(static_cast<uint32_t>(soup.size()));
  for (size_t t = 0; t < soup.size(); ++t) {
    std::array<Vec3, 3> corners = soup.corners(t);
    for (const Vec3& p : std::array<Vec3, 4>{facet_normal(corners), corners[0], corners[1], corners[2]}) {
      for (int axis = 0; axis < 3; ++axis) out.little_endian(static_cast<float>(p[axis]));
    }
    out.little_endian(uint16_t{0});  // attribute byte count
  }
}

void write_format(const TriangleSoup& soup, const std::vector<Vec3>* normals, MeshFormat format,
                  bool binary, Output& out) {
  switch (format) {
    case MeshFormat::Obj: return write_obj(soup, normals, out);
    case MeshFormat::Off: return write_off(soup, out);  // OFF has no normals
    case MeshFormat::Ply: return write_ply(soup, normals, out, binary);
    case MeshFormat::Stl: return binary ? write_stl_binary(soup, out) : write_stl_ascii(soup, out);
  }
}

bool is_binary(MeshFormat format, MeshEncoding encoding, const std::string& path) {
  bool text_only = format == MeshFormat::Obj || format == MeshFormat::Off;
  if (text_only && encoding == MeshEncoding::Binary)
    fail(path, std::string("cannot write ") + extension_of(format) + " in binary: the format is text only");
  if (text_only) return false;
  return encoding != MeshEncoding::Ascii;
}

}  // namespace

void save_mesh(const TriangleSoup& soup, const std::string& path, MeshEncoding encoding,
               const std::vector<Vec3>* vertex_normals) {
  if (vertex_normals && vertex_normals->size() != soup.vertices.size())
    fail(path, "internal error: one normal per vertex expected");
  FileFormat format = format_from_name(path);
  if (format.gzip) fail(path, "writing .gz files is not supported");
  bool binary = is_binary(format.format, encoding, path);
  if (format.format == MeshFormat::Stl && soup.size() > UINT32_MAX)
    fail(path, "too many triangles for STL, which counts them in 32 bits");

  AtomicFile file(path, "the mesh");
  Output out(file);
  write_format(soup, vertex_normals, format.format, binary, out);
  out.finish();
  file.commit();
}

}  // namespace convray::mesh
