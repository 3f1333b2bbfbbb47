// The drawn copy of an evaluated view: what the window keeps on the GPU, told of every change
// the view makes to what is drawn. The editor model knows only this interface, so it runs with
// no GL at all (tests, scripts): there the copy is a NullViewCopy that keeps nothing. The window
// gives the views a factory of GPU-backed copies (gpu_view_copy.hpp).
#pragma once

#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "render/draw_scene.hpp"

namespace pl {

class ViewCopy {
 public:
  virtual ~ViewCopy() = default;
  // Everything drawn, afresh.
  virtual void update(const DrawScene& scene) = 0;
  // The meshes and the network curves of `scene` (the control net and the combs are kept).
  virtual void update_meshes_and_curves(const DrawScene& scene) = 0;
  // The combs and borders (pointers read during the call only).
  virtual void update_curves(std::span<const CurvatureComb* const> network_combs,
                             std::span<const CurvatureComb* const> borders,
                             const std::vector<bool>& border_on_network,
                             std::span<const CurvatureComb* const> free_combs) = 0;
  // The control net and the derivative arrows drawn with it.
  virtual void set_net(const ControlNet& net, std::span<const Arrow> arrows) = 0;
};

// Keeps nothing: the copy of a view that nobody draws.
class NullViewCopy final : public ViewCopy {
 public:
  void update(const DrawScene&) override {}
  void update_meshes_and_curves(const DrawScene&) override {}
  void update_curves(std::span<const CurvatureComb* const>, std::span<const CurvatureComb* const>,
                     const std::vector<bool>&, std::span<const CurvatureComb* const>) override {}
  void set_net(const ControlNet&, std::span<const Arrow>) override {}
};

// Makes the copies; an empty factory makes NullViewCopy ones.
using ViewCopyFactory = std::function<std::unique_ptr<ViewCopy>()>;

inline std::unique_ptr<ViewCopy> make_view_copy(const ViewCopyFactory& factory) {
  if (factory) return factory();
  return std::make_unique<NullViewCopy>();
}

}  // namespace pl
