// `patchlab sample cube-sphere -o OUT.json [--cells K] [--scheme S]`: writes a
// network built from a formula (core/network/sample_networks.hpp), so that large networks for
// trying the editor, benchmarks and CAD export need not be stored or written by hand.
#include <string>

#include "app/cli/arguments.hpp"
#include "app/cli/cli.hpp"
#include "app/cli/commands.hpp"
#include "core/io/json_node.hpp"
#include "core/io/scene_io.hpp"
#include "core/network/sample_networks.hpp"
#include "core/scene/network_edit.hpp"

namespace pl {

int run_sample(std::span<const std::string> args, std::ostream& out, std::ostream&) {
  const Arguments a(args, {"-o", "--cells", "--scheme"}, {});
  if (a.positional().size() != 1 || a.positional()[0] != "cube-sphere")
    throw UsageError("sample takes the name of a sample network: cube-sphere");
  const auto target = a.value("-o");
  if (!target) throw UsageError("sample needs -o OUT.json");
  if (std::filesystem::path(*target).extension() != ".json")
    throw UsageError("sample writes a scene (.json), not \"" + *target + "\"");
  // 6 k^2 faces: k = 16 gives 1,536 faces; 64 (24,576 faces) is far beyond interactive use.
  const int cells = a.integer("--cells", 4, 1, 64);
  FaceScheme scheme = FaceScheme::Auto;
  if (const auto s = a.value("--scheme")) {
    const auto parsed = parse_scheme_keyword(*s);
    if (!parsed)
      throw UsageError("--scheme takes auto or one of " + face_scheme_keywords() + ", got \"" + *s +
                       "\"");
    scheme = *parsed;
  }
  Scene scene;
  scene.name = "cube sphere " + std::to_string(cells) + "x" + std::to_string(cells);
  scene.network = cube_sphere_network(cells, scheme);
  write_scene(*target, scene);
  out << "wrote " << printable(*target) << " (" << scene.network->faces.size() << " faces)\n";
  return kExitOk;
}

}  // namespace pl
