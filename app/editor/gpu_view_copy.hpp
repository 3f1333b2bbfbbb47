// The window's drawn copy of an evaluated view: its GPU buffers (render/gpu_scene.hpp). The
// views are given gpu_view_copies() as their factory; the painter and the screenshot read the
// buffers back with gpu_of().
#pragma once

#include "app/editor/logic/view_copy.hpp"
#include "render/gpu_scene.hpp"

namespace pl {

class GpuViewCopy final : public ViewCopy {
 public:
  void update(const DrawScene& scene) override { gpu.update(scene); }
  void update_meshes_and_curves(const DrawScene& scene) override {
    gpu.update_meshes_and_curves(scene);
  }
  void update_curves(std::span<const CurvatureComb* const> network_combs,
                     std::span<const CurvatureComb* const> borders,
                     const std::vector<bool>& border_on_network,
                     std::span<const CurvatureComb* const> free_combs) override {
    gpu.update_curves(network_combs, borders, border_on_network, free_combs);
  }
  void set_net(const ControlNet& net, std::span<const Arrow> arrows) override {
    gpu.set_net(net, arrows);
  }

  GpuScene gpu;
};

inline ViewCopyFactory gpu_view_copies() {
  return [] { return std::make_unique<GpuViewCopy>(); };
}

// The GPU buffers of a copy made by gpu_view_copies() (the window makes no other kind).
inline const GpuScene& gpu_of(const ViewCopy& copy) {
  return static_cast<const GpuViewCopy&>(copy).gpu;
}

}  // namespace pl
