// A DrawScene uploaded to the GPU. Surface attributes are converted from the core's doubles to
// floats once per upload; a surface whose revision is unchanged is not uploaded again, and a
// changed one with the same topology is updated in place (the drag path). Every surface is in one
// batch drawn with one call (GpuSurfaceBatch). Lines and points are compared with what was sent
// and only the runs that differ are sent again, so a drag frame uploads what it moved.
#pragma once

#include <span>
#include <vector>

#include "render/draw_scene.hpp"
#include "render/gl_objects.hpp"
#include "render/gpu_surface_batch.hpp"

namespace pl {

// Line segments (GL_LINES pairs) or points with a per-vertex float tag (point style, arrow kind)
// and a per-vertex offset (comb teeth: the shader draws the vertex at position + scale * offset, so
// a new comb scale needs no upload). Missing tags and offsets are not uploaded: the attribute's
// array is disabled and the shader reads the constant 0 set at draw time. set() with as many
// vertices as before sends only the runs of vertices that changed (a CPU copy of what was sent
// is kept to compare with).
class GpuPrimitives {
 public:
  GpuPrimitives();
  void set(const std::vector<Vec3>& vertices, const std::vector<float>& tags,
           const std::vector<Vec3>& offsets = {});
  // The first `count` vertices (all when negative).
  void draw(GLenum mode, GLsizei count = -1) const;
  bool empty() const { return count_ == 0; }

 private:
  // Sends scratch_ to `buffer` (whole when reallocating or the size changed, else the runs
  // that differ from `copy`) and keeps `copy` equal to what the buffer holds.
  void send(const gl::Buffer& buffer, std::vector<float>& copy, std::size_t width, bool reallocate);
  gl::VertexArray vao_;
  gl::Buffer positions_, tags_, offsets_;
  GLsizei count_ = 0;
  bool has_tags_ = false, has_offsets_ = false;
  std::vector<float> scratch_;  // reused conversion buffer
  std::vector<float> positions_copy_, tags_copy_, offsets_copy_;
};

// A set of curvature combs as two line lists: the teeth (curve point to tip) and the envelope
// through the tips, both with their offsets for the shader. The first `own` combs of set() are
// also drawable alone (own_teeth / own_envelope vertices): a scene's border combs are uploaded
// once, those that are not network edges' first.
struct GpuCombs {
  GpuPrimitives teeth, envelope;
  GLsizei own_teeth = 0, own_envelope = 0;
  // Teeth longer than max_tooth (> 0; 0: no limit) are shortened to it before the conversion to
  // float: a near-cusp tooth can exceed what a float (or the shader's length()) can hold.
  void set(std::span<const CurvatureComb* const> combs, std::size_t own, double max_tooth);
};

// Teeth are shortened on upload to this many times the reference curvature (the one that gets
// the reference length): far beyond the renderer's cap (3 reference lengths) even for a panel
// drawn with a 1000 times smaller common scale, and far below float overflow.
inline constexpr double kCombToothClamp = 1e4;

class GpuScene {
 public:
  GpuScene() = default;
  explicit GpuScene(const DrawScene& scene) { update(scene); }
  // Uploads what changed since the last call (surfaces by revision; overlays always, they are
  // small): update_geometry, the borders and the combs.
  void update(const DrawScene& scene);
  // Surfaces, control net, arrows, network curves and highlights only: the borders and combs stay
  // as they are.
  void update_geometry(const DrawScene& scene);
  // Surfaces, network curves and highlights: update_geometry without the net and arrows.
  void update_meshes_and_curves(const DrawScene& scene);
  // The control net and the derivative arrows only (the editor shows a part of its net: the part
  // that is readable at the size the surfaces have on screen).
  void set_net(const ControlNet& net, std::span<const Arrow> arrows);
  // Only the highlighted curves (the editor's picked edge).
  void set_highlights(const std::vector<Polyline>& highlights);
  // Borders (the points of `borders`) and combs held outside a DrawScene (the editor keeps them
  // once for both densities of a view); a border comb without teeth is a border without a comb;
  // `free_combs`: the combs of the free curves. Pointers are read during the call only.
  void update_curves(std::span<const CurvatureComb* const> network_combs,
                     std::span<const CurvatureComb* const> borders,
                     const std::vector<bool>& border_on_network,
                     std::span<const CurvatureComb* const> free_combs = {});
  // The drag path: re-uploads one surface's attributes (its counts unchanged).
  void update_surface(std::size_t i, const SurfaceMesh& mesh) { surfaces_.update_surface(i, mesh); }

  const GpuSurfaceBatch& surfaces() const { return surfaces_; }
  // DrawScene::closed_orientation and the box of the surfaces, as last uploaded.
  int closed_orientation() const { return closed_orientation_; }
  const Box& surface_bounds() const { return surface_bounds_; }
  // Net lines between editable points, and those touching a derived point.
  const GpuPrimitives& net_lines() const { return net_lines_; }
  const GpuPrimitives& derived_net_lines() const { return derived_net_lines_; }
  // Points tagged with point_style_tag(), derived ones first so editable ones are drawn over them.
  const GpuPrimitives& net_points() const { return net_points_; }
  // Arrows as GL_LINES pairs (base, tip) tagged with their ArrowKind.
  const GpuPrimitives& arrows() const { return arrows_; }
  const GpuPrimitives& highlights() const { return highlights_; }
  // Which point styles (bit point_style_tag) and arrow kinds (bit ArrowKind) the scene has: the
  // entries of its point key.
  uint32_t point_styles() const { return point_styles_; }
  uint32_t arrow_kinds() const { return arrow_kinds_; }
  const GpuPrimitives& network_curves() const { return curves_; }
  const GpuPrimitives& borders() const { return borders_; }
  // The first vertices of borders() that are not network curves (update_curves puts them
  // first); -1 when not known (update() from a DrawScene): every border then counts as own.
  GLsizei own_border_vertices() const { return own_border_vertices_; }
  const GpuCombs& network_combs() const { return network_combs_; }
  // The scene's free curves and their combs.
  const GpuPrimitives& free_curves() const { return free_curves_; }
  const GpuCombs& free_curve_combs() const { return free_combs_; }
  // Every border comb; those that are not also network edges' (DrawScene::border_on_network)
  // are its first own_teeth / own_envelope vertices.
  const GpuCombs& border_combs() const { return border_combs_; }
  // The automatic comb scale of this scene (tooth length per unit curvature, over the combs of
  // network curves and borders together so that coincident curves get equal teeth; 0 if every
  // curve is straight) and the tooth length it gives the reference curvature.
  double comb_scale() const { return comb_scale_; }
  double comb_reference_length() const { return comb_reference_length_; }

 private:
  void set_combs(std::span<const CurvatureComb* const> network_combs,
                 std::span<const CurvatureComb* const> borders,
                 const std::vector<bool>& border_on_network,
                 std::span<const CurvatureComb* const> free_combs = {});
  GpuSurfaceBatch surfaces_;
  int closed_orientation_ = 0;
  Box surface_bounds_;
  GLsizei own_border_vertices_ = -1;
  GpuPrimitives net_lines_, derived_net_lines_, net_points_, arrows_, curves_, borders_,
      highlights_, free_curves_;
  uint32_t point_styles_ = 0, arrow_kinds_ = 0;
  GpuCombs network_combs_, border_combs_, free_combs_;
  double diagonal_ = 0, comb_scale_ = 0, comb_reference_length_ = 0;
};

}  // namespace pl
