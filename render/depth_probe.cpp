#include "render/depth_probe.hpp"

#include <algorithm>
#include <cmath>

#include "render/gl_objects.hpp"

namespace pl {

namespace {

// Points read block by block while their rectangle is more than this many times their blocks.
constexpr std::size_t kBlockReadFactor = 16;

// The depth of `rect` (x, y, width, height in framebuffer pixels) of the bound draw
// framebuffer, row by row from the bottom.
std::vector<float> read_depth(int x, int y, int width, int height) {
  GLint draw = 0, samples = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw);
  glGetIntegerv(GL_SAMPLE_BUFFERS, &samples);
  std::vector<float> depth(std::size_t(width) * height, 1.0f);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  GLint read = 0;
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read);
  if (samples == 0) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(draw));
    glReadPixels(x, y, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  } else {
    // A multisampled buffer is read through a single-sampled copy of the rectangle alone (of the
    // same format, as a depth blit needs; desktop GL asks a resolving blit for equal sizes only,
    // so the copy starts at its origin and is no larger than what is read).
    gl::Renderbuffer copy;
    gl::Framebuffer fbo;
    glBindRenderbuffer(GL_RENDERBUFFER, copy.id());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(draw));
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo.id());
    glFramebufferRenderbuffer(GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, copy.id());
    glDrawBuffer(GL_NONE);  // depth only: complete without a colour attachment
    glBlitFramebuffer(x, y, x + width, y + height, 0, 0, width, height, GL_DEPTH_BUFFER_BIT,
                      GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo.id());
    glReadBuffer(GL_NONE);
    glReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(draw));
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(read));
  gl::check_error("points_seen");
  return depth;
}

}  // namespace

std::vector<char> points_seen(const Camera& camera, const Viewport& v,
                              std::span<const Vec3> points) {
  std::vector<char> seen(points.size(), 1);
  if (points.empty() || v.width < 1 || v.height < 1) return seen;
  const glm::dmat4 vp = camera.projection(double(v.width) / double(v.height)) * camera.view();
  // Each point's framebuffer pixel and window depth; -1 where there is nothing to read.
  struct At {
    int x = -1, y = -1;
    double depth = 0;
  };
  std::vector<At> at(points.size());
  int x0 = v.x + v.width, y0 = v.y + v.height, x1 = v.x - 1, y1 = v.y - 1;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const glm::dvec4 c = vp * glm::dvec4(points[i], 1.0);
    if (!(c.w > 0)) {
      seen[i] = 0;
      continue;
    }
    const double ndc_z = c.z / c.w;
    if (!(ndc_z >= -1 && ndc_z <= 1)) {  // cut by a clipping plane, as GL cuts the curve
      seen[i] = 0;
      continue;
    }
    const double px = v.x + (c.x / c.w * 0.5 + 0.5) * v.width;
    const double py = v.y + (c.y / c.w * 0.5 + 0.5) * v.height;
    if (!(px >= v.x && px < v.x + v.width && py >= v.y && py < v.y + v.height)) continue;
    // As the line shader pulls overlays forward: NDC depth less the bias, to window depth.
    at[i] = {int(px), int(py), 0.5 * (ndc_z - kOverlayDepthBias) + 0.5};
    x0 = std::min(x0, at[i].x - 1), x1 = std::max(x1, at[i].x + 1);
    y0 = std::min(y0, at[i].y - 1), y1 = std::max(y1, at[i].y + 1);
  }
  x0 = std::max(x0, v.x), y0 = std::max(y0, v.y);
  x1 = std::min(x1, v.x + v.width - 1), y1 = std::min(y1, v.y + v.height - 1);
  if (x1 < x0 || y1 < y0) return seen;
  // The farthest depth of the 3 x 3 pixels around each point, read from `depth` (the rectangle
  // from (rx, ry), rw wide) clamped to [x0, x1] x [y0, y1].
  auto decide = [&](std::size_t i, const std::vector<float>& depth, int rx, int ry, int rw) {
    float farthest = 0;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int qx = std::clamp(at[i].x + dx, x0, x1) - rx;
        const int qy = std::clamp(at[i].y + dy, y0, y1) - ry;
        farthest = std::max(farthest, depth[std::size_t(qy) * rw + qx]);
      }
    seen[i] = at[i].depth <= double(farthest) ? 1 : 0;
  };
  const int w = x1 - x0 + 1, h = y1 - y0 + 1;
  std::size_t inside = 0;
  for (const At& a : at) inside += a.x >= 0;
  // A few marks spread over the view: their 3 x 3 blocks alone, not the whole rectangle they
  // span (a full-view read and resolve every frame is what a drag would pay).
  if (std::size_t(w) * std::size_t(h) > kBlockReadFactor * 9 * inside) {
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (at[i].x < 0) continue;
      const int bx = std::max(at[i].x - 1, x0), by = std::max(at[i].y - 1, y0);
      const int bw = std::min(at[i].x + 1, x1) - bx + 1, bh = std::min(at[i].y + 1, y1) - by + 1;
      decide(i, read_depth(bx, by, bw, bh), bx, by, bw);
    }
    return seen;
  }
  const std::vector<float> depth = read_depth(x0, y0, w, h);
  for (std::size_t i = 0; i < points.size(); ++i)
    if (at[i].x >= 0) decide(i, depth, x0, y0, w);
  return seen;
}

}  // namespace pl
