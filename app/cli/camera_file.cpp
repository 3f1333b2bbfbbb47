#include "app/cli/camera_file.hpp"

#include <algorithm>
#include <cmath>

#include "core/io/atomic_file.hpp"
#include "core/io/json_node.hpp"

namespace pl {

namespace {
constexpr double kDegree = 3.14159265358979323846 / 180.0;
}

Camera read_camera_file(const std::filesystem::path& path, const Box& box, double aspect) {
  const std::string source = path.string();
  const nlohmann::json doc = parse_json(read_text_file(path), source);
  const JsonNode root(doc, source);
  root.require_object();
  root.allow_only({"target", "eye", "yaw_deg", "pitch_deg", "distance", "fov_deg", "projection"});

  Camera c = preset_camera(ViewPreset::Iso, box, aspect);
  if (auto p = root.find("projection")) {
    const std::string s = p->string();
    if (s != "perspective" && s != "orthographic")
      p->fail("expected \"perspective\" or \"orthographic\", got \"" + s + "\"");
    c.orthographic = s == "orthographic";
  }
  if (auto f = root.find("fov_deg")) {
    const double v = f->number();
    if (!(v > 1 && v < 170)) f->fail("field of view must be between 1 and 170 degrees");
    c.fov_y = v * kDegree;
  }
  if (auto y = root.find("yaw_deg")) c.yaw = y->number() * kDegree;
  if (auto p = root.find("pitch_deg")) {
    const double v = p->number();
    if (v < -90 || v > 90) p->fail("pitch must be between -90 and 90 degrees");
    c.pitch = v * kDegree;
  }
  c.frame(box, aspect);  // target and distance for these angles
  if (auto t = root.find("target")) c.target = t->point();
  if (auto e = root.find("eye")) {
    const Vec3 d = e->point() - c.target;
    const double len = glm::length(d);
    if (!(len > 0)) e->fail("eye coincides with the target");
    c.distance = len;
    c.yaw = std::atan2(d.y, d.x);
    c.pitch = std::asin(std::clamp(d.z / len, -1.0, 1.0));
  }
  if (auto dist = root.find("distance")) {
    const double v = dist->number();
    if (!(v > 0)) dist->fail("distance must be positive");
    c.distance = v;
  }
  // The clipping planes must still enclose the scene when the target is off its centre.
  c.scene_radius = box.empty() ? 1.0 : box.radius() + glm::length(c.target - box.centre());
  return c;
}

}  // namespace pl
