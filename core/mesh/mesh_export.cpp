// Every format is written by hand through stdio, so that each write error (disk full, file too
// large) is seen and reported: OpenMesh 9's writers ignore the stream state and report success
// for a truncated file. The CLI contract also asks for one named object ("o NAME") per patch in
// OBJ, which OpenMesh's OBJ writer cannot express, and for double precision in PLY. Nothing is
// written before every sample is checked finite (core/mesh/finite_check.hpp).
#include "core/mesh/mesh_export.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "core/base/data_error.hpp"
#include "core/base/parallel_for.hpp"
#include "core/io/atomic_file.hpp"
#include "core/mesh/finite_check.hpp"

namespace pl {

namespace {

std::FILE* open_for_writing(const std::filesystem::path& tmp, const std::filesystem::path& target) {
  errno = 0;
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) throw_write_error(target, errno);
  std::setvbuf(f, nullptr, _IOFBF, 1 << 20);  // a few hundred writes for a large OBJ, not 50,000
  return f;
}

// Flushes and closes f; a write error anywhere before (disk full, file too large) shows here.
void finish(std::FILE* f, const std::filesystem::path& target) {
  int e = 0;
  if (std::ferror(f)) e = errno ? errno : EIO;
  if (std::fflush(f) != 0 && !e) e = errno;
  if (std::fclose(f) != 0 && !e) e = errno;
  if (e) throw_write_error(target, e);
}

// Numbers as "%.17g" prints them: std::to_chars with that precision is specified to give
// printf's text (C locale), and costs a fraction of it. glibc's printf converts a double exactly
// through multi-precision arithmetic, slower the larger the number: on a curve of 400,000 points
// drawn out to x = 4,000 that was a third of the OBJ export.
class NumberLine {
 public:
  explicit NumberLine(const char* prefix) : end_(buf_) { put(prefix); }
  NumberLine& operator<<(double x) {
    if (end_ != buf_) *end_++ = ' ';  // after the prefix or the number before
    end_ = std::to_chars(end_, buf_ + sizeof buf_, x, std::chars_format::general, 17).ptr;
    return *this;
  }
  NumberLine& operator<<(const Vec3& p) { return *this << p.x << p.y << p.z; }
  void append_to(std::string& out) {
    *end_++ = '\n';
    out.append(buf_, end_);
  }

 private:
  void put(const char* s) {
    while (*s) *end_++ = *s++;
  }
  char buf_[16 + 10 * 32];  // a prefix and up to ten numbers of at most 24 characters
  char* end_;
};

// Appends i (and a separator before it) to out.
void append_index(std::string& out, char before, std::size_t i) {
  char buf[32];
  buf[0] = before;
  out.append(buf, std::to_chars(buf + 1, buf + sizeof buf, i).ptr);
}

// A text file in pieces, each formatted on its own into a string: the pieces of a batch are
// formatted over the cores and written in their order, so the file is the same bytes as one
// thread would write, with at most a batch of text (kBatch pieces of at most kLines lines) held
// at once.
class OrderedText {
 public:
  static constexpr std::size_t kLines = 4096, kBatch = 64;

  void add(std::function<void(std::string&)> piece) { pieces_.push_back(std::move(piece)); }
  // One piece per kLines of `count` lines, line(i, out) appending line i.
  template <class Line>
  void add_lines(std::size_t count, Line line) {
    for (std::size_t b = 0; b < count; b += kLines)
      add([line, b, e = std::min(count, b + kLines)](std::string& out) {
        for (std::size_t i = b; i < e; ++i) line(i, out);
      });
  }
  void write(std::FILE* f) const {
    std::vector<std::string> text(kBatch);
    for (std::size_t b = 0; b < pieces_.size(); b += kBatch) {
      const std::size_t e = std::min(pieces_.size(), b + kBatch);
      parallel_each(e - b, 1, [&](std::size_t i) {
        text[i].clear();
        pieces_[b + i](text[i]);
      });
      for (std::size_t i = 0; i < e - b; ++i) std::fwrite(text[i].data(), 1, text[i].size(), f);
    }
  }

 private:
  std::vector<std::function<void(std::string&)>> pieces_;
};

// The facet normal: the triangle's own, or where the triangle has no area (two samples coincide,
// as at the pole of a sphere) the mean of its three exact vertex normals, the limit of the facet
// normals around it.
Vec3 facet_normal(const SurfaceMesh& m, const std::array<uint32_t, 3>& t) {
  const Vec3 &a = m.positions[t[0]], &b = m.positions[t[1]], &c = m.positions[t[2]];
  Vec3 n = glm::cross(b - a, c - a);
  const double s = std::max({glm::length(b - a), glm::length(c - a), glm::length(c - b)});
  if (!(glm::length(n) > 1e-12 * s * s)) n = m.normals[t[0]] + m.normals[t[1]] + m.normals[t[2]];
  if (!(glm::length(n) > 0)) n = m.normals[t[0]];
  return glm::normalize(n);
}

void write_obj(const std::vector<SurfaceMesh>& meshes, const std::vector<CurvePolyline>& polylines,
               std::FILE* f) {
  OrderedText text;
  text.add([](std::string& out) { out += std::string("# PatchLab ") + PATCHLAB_VERSION + "\n"; });
  std::size_t base = 1;
  for (const SurfaceMesh& m : meshes) {
    text.add([&m](std::string& out) { out += "o " + m.name + "\n"; });
    text.add_lines(m.positions.size(), [&m](std::size_t i, std::string& out) {
      (NumberLine("v") << m.positions[i]).append_to(out);
    });
    text.add_lines(m.normals.size(), [&m](std::size_t i, std::string& out) {
      (NumberLine("vn") << m.normals[i]).append_to(out);
    });
    text.add_lines(m.triangles.size(), [&m, base](std::size_t i, std::string& out) {
      out += 'f';
      for (uint32_t v : m.triangles[i]) {  // " a//a": position and normal a
        append_index(out, ' ', v + base);
        out += '/';
        append_index(out, '/', v + base);
      }
      out += '\n';
    });
    base += m.positions.size();
  }
  for (const CurvePolyline& l : polylines) {
    text.add([&l](std::string& out) { out += "o " + l.name + "\n"; });
    text.add_lines(l.points.size(), [&l](std::size_t i, std::string& out) {
      (NumberLine("v") << l.points[i]).append_to(out);
    });
    text.add([&l, base](std::string& out) {
      out += 'l';
      for (std::size_t i = 0; i < l.points.size(); ++i) append_index(out, ' ', base + i);
      out += '\n';
    });
    base += l.points.size();
  }
  text.write(f);
}

// "3 a b c" for triangle i of m, its indices offset by base.
void append_triangle(std::string& out, const SurfaceMesh& m, std::size_t i, std::size_t base) {
  out += '3';
  for (uint32_t v : m.triangles[i]) append_index(out, ' ', v + base);
  out += '\n';
}

void write_ply(const std::vector<SurfaceMesh>& meshes, std::FILE* f) {
  std::size_t nv = 0, nf = 0;
  for (const SurfaceMesh& m : meshes) nv += m.positions.size(), nf += m.triangles.size();
  std::fprintf(f,
               "ply\nformat ascii 1.0\ncomment PatchLab %s: exact normals and curvatures\n"
               "element vertex %zu\n"
               "property double x\nproperty double y\nproperty double z\n"
               "property double nx\nproperty double ny\nproperty double nz\n"
               "property double mean_curvature\nproperty double gaussian_curvature\n"
               "property double k_min\nproperty double k_max\n"
               "element face %zu\nproperty list uchar uint vertex_indices\nend_header\n",
               PATCHLAB_VERSION, nv, nf);
  OrderedText text;
  for (const SurfaceMesh& m : meshes)
    text.add_lines(m.positions.size(), [&m](std::size_t i, std::string& out) {
      (NumberLine("") << m.positions[i] << m.normals[i] << m.mean[i] << m.gaussian[i] << m.kmin[i]
                      << m.kmax[i])
          .append_to(out);
    });
  std::size_t base = 0;
  for (const SurfaceMesh& m : meshes) {
    text.add_lines(m.triangles.size(), [&m, base](std::size_t i, std::string& out) {
      append_triangle(out, m, i, base);
    });
    base += m.positions.size();
  }
  text.write(f);
}

// OFF: positions and triangles, all patches in one mesh (OFF has no objects).
void write_off(const std::vector<SurfaceMesh>& meshes, std::FILE* f) {
  std::size_t nv = 0, nf = 0;
  for (const SurfaceMesh& m : meshes) nv += m.positions.size(), nf += m.triangles.size();
  std::fprintf(f, "OFF\n%zu %zu 0\n", nv, nf);
  OrderedText text;
  for (const SurfaceMesh& m : meshes)
    text.add_lines(m.positions.size(), [&m](std::size_t i, std::string& out) {
      (NumberLine("") << m.positions[i]).append_to(out);
    });
  std::size_t base = 0;
  for (const SurfaceMesh& m : meshes) {
    text.add_lines(m.triangles.size(), [&m, base](std::size_t i, std::string& out) {
      append_triangle(out, m, i, base);
    });
    base += m.positions.size();
  }
  text.write(f);
}

// Binary STL (little-endian, single precision by definition): an 80-byte header, the facet
// count, then per facet its normal, three corners and a zero attribute word.
void write_stl(const std::vector<SurfaceMesh>& meshes, std::FILE* f) {
  char header[80] = {};
  std::snprintf(header, sizeof header, "PatchLab %s binary STL", PATCHLAB_VERSION);
  std::fwrite(header, 1, sizeof header, f);
  std::size_t nf = 0;
  for (const SurfaceMesh& m : meshes) nf += m.triangles.size();
  const uint32_t count = static_cast<uint32_t>(std::min<std::size_t>(nf, UINT32_MAX));
  std::fwrite(&count, sizeof count, 1, f);
  for (const SurfaceMesh& m : meshes)
    for (const auto& t : m.triangles) {
      float rec[12];
      const Vec3 n = facet_normal(m, t);
      const Vec3* v[4] = {&n, &m.positions[t[0]], &m.positions[t[1]], &m.positions[t[2]]};
      for (int k = 0; k < 4; ++k)
        for (int c = 0; c < 3; ++c) rec[3 * k + c] = static_cast<float>((*v[k])[c]);
      const uint16_t attribute = 0;
      std::fwrite(rec, sizeof rec, 1, f);
      std::fwrite(&attribute, sizeof attribute, 1, f);
    }
}

}  // namespace

std::optional<MeshFormat> find_mesh_format(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (ext == ".obj") return MeshFormat::Obj;
  if (ext == ".ply") return MeshFormat::Ply;
  if (ext == ".off") return MeshFormat::Off;
  if (ext == ".stl") return MeshFormat::Stl;
  return std::nullopt;
}

MeshFormat mesh_format_for(const std::filesystem::path& path) {
  if (const auto f = find_mesh_format(path)) return *f;
  const std::string ext = path.extension().string();
  throw DataError(path.string(), "",
                  "unknown mesh format \"" + ext + "\" (use .obj, .ply, .off or .stl)");
}

void export_meshes(const std::vector<SurfaceMesh>& meshes, const std::filesystem::path& path,
                   const std::string& source, const std::vector<CurvePolyline>& polylines) {
  const MeshFormat format = mesh_format_for(path);
  check_finite(meshes, source.empty() ? path.string() : source);
  for (const CurvePolyline& l : polylines)
    for (std::size_t i = 0; i < l.points.size(); ++i)
      if (!std::isfinite(l.points[i].x + l.points[i].y + l.points[i].z))
        throw DataError(source.empty() ? path.string() : source, l.name,
                        "curve sample " + std::to_string(i) + " is not finite");
  write_atomically_via(path, [&](const std::filesystem::path& tmp) {
    std::FILE* f = open_for_writing(tmp, path);
    switch (format) {
      case MeshFormat::Obj:
        write_obj(meshes, polylines, f);
        break;
      case MeshFormat::Ply:
        write_ply(meshes, f);
        break;
      case MeshFormat::Off:
        write_off(meshes, f);
        break;
      case MeshFormat::Stl:
        write_stl(meshes, f);
        break;
    }
    finish(f, path);
  });
}

}  // namespace pl
