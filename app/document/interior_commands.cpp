#include "app/document/interior_commands.hpp"

#include "core/base/data_error.hpp"
#include "core/network/gb_face_free_points.hpp"
#include "core/network/gb_face_interior.hpp"
#include "core/network/network_filling.hpp"

namespace pl {

namespace {

std::string str(int i) {
  return std::to_string(i);
}

NetworkFace& interior_face(Scene& scene, int face) {
  if (const std::string why = no_interior_reason(scene, face); !why.empty()) throw EditRefused(why);
  return scene.network->faces[face];
}

// The face must still be one the filling can build (a central point needs a domain that can
// weight it); otherwise the edit is refused with the reason.
void check_face(const Network& net, const NetworkTopology& topo, int face) {
  try {
    check_fillable_near(net, topo, net.faces[face].loop, "");
  } catch (const DataError& e) {
    throw EditRefused("face " + str(face) + " cannot be filled so: " + std::string(e.what()));
  }
}

}  // namespace

std::string no_interior_reason(const Scene& scene, int face) {
  if (!scene.network) return "the scene has no curve network";
  if (face < 0 || face >= int(scene.network->faces.size()))
    return "face " + str(face) + " does not exist";
  if (!is_gb_face(scene, face))
    return "face " + str(face) +
           " is a Gregory face: Gregory faces have no free interior (all their inner points are "
           "G1 data)";
  return "";
}

void SetFaceDegreeCommand::apply(Scene& scene) {
  NetworkFace& face = interior_face(scene, face_);
  if (degree_ < 3 || degree_ > kMaxGBFaceDegree)
    throw EditRefused("a GB face's degree is 3 to " + str(kMaxGBFaceDegree) + " (asked for " +
                      str(degree_) + ")");
  if (degree_ == face.degree)
    throw EditRefused("face " + str(face_) + " already has degree " + str(degree_));
  Network& net = *scene.network;
  const NetworkTopology topo = validate_network(net, "");
  if (!face.offsets.empty())
    face.offsets = gb_face_offsets_for_degree(local_face_ribbons(net, topo, face_), face.degree,
                                              face.offsets, degree_);
  face.degree = degree_;
  check_face(net, topo, face_);
}

std::string SetFaceDegreeCommand::label() const {
  return "face " + str(face_) + " degree " + str(degree_);
}

void ResetInteriorCommand::apply(Scene& scene) {
  NetworkFace& face = interior_face(scene, face_);
  if (face.offsets.empty())
    throw EditRefused("the interior of face " + str(face_) + " is already at its defaults");
  face.offsets.clear();
}

std::string ResetInteriorCommand::label() const {
  return "reset the interior of face " + str(face_);
}

}  // namespace pl
