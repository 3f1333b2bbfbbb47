#include "core/network/network_filling.hpp"

#include "core/io/data_error.hpp"

namespace pl {

NetworkFilling fill_network(const Network& network, const NetworkTopology&,
                            std::optional<FaceScheme>, const std::string& source) {
  // Gregory (issue #3) and GB (issue #4) face filling are not built yet: say so instead of
  // producing a surface that is not the one the file describes.
  if (!network.faces.empty())
    throw DataError(source, "network.faces[0]",
                    "filling network faces is not available in this version");
  return {};
}

}  // namespace pl
