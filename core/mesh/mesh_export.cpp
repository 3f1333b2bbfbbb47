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

#include "core/base/data_error.hpp"
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
  void write(std::FILE* f) {
    *end_++ = '\n';
    std::fwrite(buf_, 1, end_ - buf_, f);
  }

 private:
  void put(const char* s) {
    while (*s) *end_++ = *s++;
  }
  char buf_[16 + 10 * 32];  // a prefix and up to ten numbers of at most 24 characters
  char* end_;
};

// " i" for each index from `first` on, `count` of them, and the end of the line.
void write_indices(std::FILE* f, std::size_t first, std::size_t count) {
  char buf[32];
  for (std::size_t i = first; i < first + count; ++i) {
    buf[0] = ' ';
    char* end = std::to_chars(buf + 1, buf + sizeof buf, i).ptr;
    std::fwrite(buf, 1, end - buf, f);
  }
  std::fputc('\n', f);
}

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
  std::fprintf(f, "# PatchLab %s\n", PATCHLAB_VERSION);
  std::size_t base = 1;
  for (const SurfaceMesh& m : meshes) {
    std::fprintf(f, "o %s\n", m.name.c_str());
    for (const Vec3& p : m.positions) (NumberLine("v") << p).write(f);
    for (const Vec3& n : m.normals) (NumberLine("vn") << n).write(f);
    for (const auto& t : m.triangles) {
      const std::size_t a = t[0] + base, b = t[1] + base, c = t[2] + base;
      std::fprintf(f, "f %zu//%zu %zu//%zu %zu//%zu\n", a, a, b, b, c, c);
    }
    base += m.positions.size();
  }
  for (const CurvePolyline& l : polylines) {
    std::fprintf(f, "o %s\n", l.name.c_str());
    for (const Vec3& p : l.points) (NumberLine("v") << p).write(f);
    std::fputc('l', f);
    write_indices(f, base, l.points.size());
    base += l.points.size();
  }
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
  for (const SurfaceMesh& m : meshes)
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
      const Vec3 &p = m.positions[i], &n = m.normals[i];
      (NumberLine("") << p << n << m.mean[i] << m.gaussian[i] << m.kmin[i] << m.kmax[i]).write(f);
    }
  std::size_t base = 0;
  for (const SurfaceMesh& m : meshes) {
    for (const auto& t : m.triangles)
      std::fprintf(f, "3 %zu %zu %zu\n", t[0] + base, t[1] + base, t[2] + base);
    base += m.positions.size();
  }
}

// OFF: positions and triangles, all patches in one mesh (OFF has no objects).
void write_off(const std::vector<SurfaceMesh>& meshes, std::FILE* f) {
  std::size_t nv = 0, nf = 0;
  for (const SurfaceMesh& m : meshes) nv += m.positions.size(), nf += m.triangles.size();
  std::fprintf(f, "OFF\n%zu %zu 0\n", nv, nf);
  for (const SurfaceMesh& m : meshes)
    for (const Vec3& p : m.positions) (NumberLine("") << p).write(f);
  std::size_t base = 0;
  for (const SurfaceMesh& m : meshes) {
    for (const auto& t : m.triangles)
      std::fprintf(f, "3 %zu %zu %zu\n", t[0] + base, t[1] + base, t[2] + base);
    base += m.positions.size();
  }
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
