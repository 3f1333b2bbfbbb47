// Whole scenes over the cores: a network's faces filled and evaluated side by side
// (evaluate_scene), the mesh files' text formatted in pieces side by side and written in order
// (export_meshes). The results are the same bytes on one thread and on many, the first bad face is
// the one reported whatever the threads, and the OBJ text reads back to the exact samples.
#include <gtest/gtest.h>
#include <oneapi/tbb/global_control.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "core/base/data_error.hpp"
#include "core/domain/tessellation_cache.hpp"
#include "core/eval/scene_surfaces.hpp"
#include "core/mesh/mesh_export.hpp"
#include "core/mesh/surface_mesh.hpp"
#include "core/network/sample_networks.hpp"

namespace pl {
namespace {

std::string read_all(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A folder of this process's own, removed at the end.
struct TempDir {
  TempDir()
      : dir(std::filesystem::temp_directory_path() /
            ("patchlab-parallel-scene-" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(dir);
  }
  ~TempDir() { std::filesystem::remove_all(dir); }
  const std::filesystem::path& path() const { return dir; }
  std::filesystem::path dir;
};

std::vector<SurfaceMesh> meshes_of(const Scene& scene, int density) {
  TessellationCache cache;
  const SceneSurfaces ss = evaluate_scene(scene, density, std::nullopt, cache, "sphere");
  std::vector<SurfaceMesh> meshes;
  for (const SceneSurface& s : ss.surfaces)
    meshes.push_back(make_surface_mesh(*s.evaluator, s.name));
  return meshes;
}

TEST(ParallelScene, MeshFilesAreTheSameBytesOnOneThreadAndManyAndReadBackExactly) {
  Scene scene;
  scene.network = cube_sphere_network(3, FaceScheme::GB);  // 54 faces
  // Density 70: 5,041 samples a face, so a face's lines are split into pieces, and 54 faces give
  // more pieces than one batch holds.
  const int density = 70;
  const TempDir dir;
  std::vector<SurfaceMesh> one_meshes;
  std::map<std::string, std::string> one;
  {
    const oneapi::tbb::global_control single(oneapi::tbb::global_control::max_allowed_parallelism,
                                             1);
    one_meshes = meshes_of(scene, density);
    for (const char* ext : {".obj", ".ply", ".off", ".stl"}) {
      export_meshes(one_meshes, dir.path() / (std::string("one") + ext), "sphere");
      one[ext] = read_all(dir.path() / (std::string("one") + ext));
    }
  }
  const std::vector<SurfaceMesh> many_meshes = meshes_of(scene, density);
  ASSERT_EQ(many_meshes.size(), 54u);
  for (const char* ext : {".obj", ".ply", ".off", ".stl"}) {
    export_meshes(many_meshes, dir.path() / (std::string("many") + ext), "sphere");
    EXPECT_EQ(read_all(dir.path() / (std::string("many") + ext)), one[ext]) << ext;
  }
  // The OBJ read back: every v line the exact position, every f line the right global indices.
  std::istringstream obj(one[".obj"]);
  std::string line;
  std::size_t mesh = std::size_t(-1), v = 0, vn = 0, f = 0, base = 1;
  bool exact = true, indices = true;
  while (std::getline(obj, line)) {
    std::istringstream ls(line);
    std::string tag;
    ls >> tag;
    if (tag == "o") {
      if (mesh != std::size_t(-1)) base += one_meshes[mesh].positions.size();
      ++mesh, v = vn = f = 0;
    } else if (tag == "v") {
      std::string x, y, z;
      ls >> x >> y >> z;
      const Vec3& p = one_meshes[mesh].positions[v++];
      exact = exact && std::strtod(x.c_str(), nullptr) == p.x &&
              std::strtod(y.c_str(), nullptr) == p.y && std::strtod(z.c_str(), nullptr) == p.z;
    } else if (tag == "vn") {
      ++vn;
    } else if (tag == "f") {
      const auto& t = one_meshes[mesh].triangles[f++];
      for (int k = 0; k < 3; ++k) {
        std::string corner;
        ls >> corner;
        const std::string want = std::to_string(t[k] + base);
        indices = indices && corner == want + "//" + want;
      }
    }
  }
  EXPECT_EQ(mesh + 1, one_meshes.size());
  EXPECT_TRUE(exact);
  EXPECT_TRUE(indices);
}

TEST(ParallelScene, TheFirstBadFaceIsReportedWhateverTheThreads) {
  // Two faces made unfillable (a degree no GB face has); the message names the lower one on one
  // thread and on many.
  Scene scene;
  scene.network = cube_sphere_network(3, FaceScheme::GB);
  Network& net = *scene.network;
  std::string one, many;
  net.faces[12].degree = 0;  // not a GB degree: the face is refused by its build
  net.faces[40].degree = 0;
  const auto message = [&] {
    try {
      TessellationCache cache;
      evaluate_scene(scene, 8, std::nullopt, cache, "sphere.json");
    } catch (const DataError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  {
    const oneapi::tbb::global_control single(oneapi::tbb::global_control::max_allowed_parallelism,
                                             1);
    one = message();
  }
  many = message();
  std::printf("[ first bad face ] %s\n", one.c_str());
  EXPECT_NE(one.find("12"), std::string::npos) << one;
  EXPECT_EQ(one, many);
}

}  // namespace
}  // namespace pl
