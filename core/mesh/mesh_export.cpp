// OBJ and PLY are written by hand: the CLI contract asks for one named object ("o NAME") per patch
// in OBJ, which OpenMesh's OBJ writer cannot express, and OpenMesh 9's PLY writer stores positions
// and normals as 32-bit floats even for double meshes, which would throw away the exact normals.
// OFF and STL (single precision by definition) go through OpenMesh.
#include "core/mesh/mesh_export.hpp"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>

#include "core/io/atomic_file.hpp"
#include "core/base/data_error.hpp"

namespace pl {

namespace {

struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
  VertexAttributes(OpenMesh::Attributes::Normal);
};
using OMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;

void write_obj(const std::vector<SurfaceMesh>& meshes, const std::filesystem::path& tmp) {
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) throw DataError(tmp.string(), "", "cannot write");
  std::fprintf(f, "# PatchLab %s\n", PATCHLAB_VERSION);
  std::size_t base = 1;
  for (const SurfaceMesh& m : meshes) {
    std::fprintf(f, "o %s\n", m.name.c_str());
    for (const Vec3& p : m.positions) std::fprintf(f, "v %.17g %.17g %.17g\n", p.x, p.y, p.z);
    for (const Vec3& n : m.normals) std::fprintf(f, "vn %.17g %.17g %.17g\n", n.x, n.y, n.z);
    for (const auto& t : m.triangles) {
      const std::size_t a = t[0] + base, b = t[1] + base, c = t[2] + base;
      std::fprintf(f, "f %zu//%zu %zu//%zu %zu//%zu\n", a, a, b, b, c, c);
    }
    base += m.positions.size();
  }
  const bool ok = std::fflush(f) == 0 && !std::ferror(f);
  std::fclose(f);
  if (!ok) throw DataError(tmp.string(), "", "write failed (disk full?)");
}

void write_ply(const std::vector<SurfaceMesh>& meshes, const std::filesystem::path& tmp) {
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) throw DataError(tmp.string(), "", "cannot write");
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
      std::fprintf(f, "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", p.x, p.y,
                   p.z, n.x, n.y, n.z, m.mean[i], m.gaussian[i], m.kmin[i], m.kmax[i]);
    }
  std::size_t base = 0;
  for (const SurfaceMesh& m : meshes) {
    for (const auto& t : m.triangles)
      std::fprintf(f, "3 %zu %zu %zu\n", t[0] + base, t[1] + base, t[2] + base);
    base += m.positions.size();
  }
  const bool ok = std::fflush(f) == 0 && !std::ferror(f);
  std::fclose(f);
  if (!ok) throw DataError(tmp.string(), "", "write failed (disk full?)");
}

void write_with_openmesh(const std::vector<SurfaceMesh>& meshes, const std::filesystem::path& tmp,
                         MeshFormat format) {
  OMesh mesh;
  for (const SurfaceMesh& m : meshes) {
    std::vector<OMesh::VertexHandle> vh;
    vh.reserve(m.positions.size());
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
      const Vec3& p = m.positions[i];
      const Vec3& n = m.normals[i];
      auto h = mesh.add_vertex(OpenMesh::Vec3d(p.x, p.y, p.z));
      mesh.set_normal(h, OpenMesh::Vec3d(n.x, n.y, n.z));
      vh.push_back(h);
    }
    for (const auto& t : m.triangles) mesh.add_face(vh[t[0]], vh[t[1]], vh[t[2]]);
  }
  OpenMesh::IO::Options opt;
  if (format == MeshFormat::Stl) opt += OpenMesh::IO::Options::Binary;
  // OpenMesh picks the writer from the extension, so give the temporary file the right one.
  // Its writers chat on stdout ("write binary file"); a CLI's stdout is for results only.
  omlog().disable();
  omout().disable();
  const bool written = OpenMesh::IO::write_mesh(mesh, tmp.string(), opt, 17);
  omout().enable();
  omlog().enable();
  if (!written) throw DataError(tmp.string(), "", "OpenMesh could not write the mesh");
}

}  // namespace

MeshFormat mesh_format_for(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (ext == ".obj") return MeshFormat::Obj;
  if (ext == ".ply") return MeshFormat::Ply;
  if (ext == ".off") return MeshFormat::Off;
  if (ext == ".stl") return MeshFormat::Stl;
  throw DataError(path.string(), "",
                  "unknown mesh format \"" + ext + "\" (use .obj, .ply, .off or .stl)");
}

void export_meshes(const std::vector<SurfaceMesh>& meshes, const std::filesystem::path& path) {
  const MeshFormat format = mesh_format_for(path);
  write_atomically_via(path, [&](const std::filesystem::path& tmp_in) {
    // Keep the extension on the temporary name (OpenMesh chooses its writer by it).
    const std::filesystem::path tmp = tmp_in.string() + path.extension().string();
    try {
      if (format == MeshFormat::Obj)
        write_obj(meshes, tmp);
      else if (format == MeshFormat::Ply)
        write_ply(meshes, tmp);
      else
        write_with_openmesh(meshes, tmp, format);
      std::filesystem::rename(tmp, tmp_in);
    } catch (...) {
      std::error_code ignore;
      std::filesystem::remove(tmp, ignore);
      throw;
    }
  });
}

}  // namespace pl
