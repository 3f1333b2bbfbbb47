#include "core/domain/domain_from_boundary.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pl {

void fit_unit_box(std::vector<Vec2>& points) {
  Vec2 lo = points[0], hi = points[0];
  for (const Vec2& p : points) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const double size = std::max(hi.x - lo.x, hi.y - lo.y);
  const Vec2 mid = 0.5 * (lo + hi);
  for (Vec2& p : points) p = (p - mid) * (2.0 / size);
}

std::vector<Vec2> project_to_best_fit_plane(const std::vector<Vec3>& corners) {
  const std::size_t n = corners.size();
  if (n < 3) throw std::invalid_argument("a face domain needs at least 3 corners");
  Vec3 centre(0);
  for (const Vec3& p : corners) centre += p;
  centre /= double(n);
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Vec3& p : corners) {
    const Eigen::Vector3d d(p.x - centre.x, p.y - centre.y, p.z - centre.z);
    cov += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  const Eigen::Vector3d ev = eig.eigenvalues();  // ascending
  // The covariance carries rounding noise of about 1e-16 ev(2): a second eigenvalue below
  // 1e-12 ev(2) (width under 1e-6 of the length) is a collinear loop.
  if (!(ev(1) > 1e-12 * ev(2))) throw std::invalid_argument("the face's corners are collinear");
  Vec3 normal(eig.eigenvectors()(0, 0), eig.eigenvectors()(1, 0), eig.eigenvectors()(2, 0));
  // Orientation from the loop itself (Newell), not from the eigen solver's arbitrary sign.
  Vec3 newell(0);
  for (std::size_t i = 0; i < n; ++i) newell += glm::cross(corners[i], corners[(i + 1) % n]);
  if (glm::dot(newell, normal) < 0) normal = -normal;
  const Vec3 ex(eig.eigenvectors()(0, 2), eig.eigenvectors()(1, 2), eig.eigenvectors()(2, 2));
  const Vec3 ey = glm::cross(normal, ex);
  std::vector<Vec2> out;
  for (const Vec3& p : corners)
    out.emplace_back(glm::dot(p - centre, ex), glm::dot(p - centre, ey));
  fit_unit_box(out);
  return out;
}

std::optional<std::vector<Vec2>> angle_length_domain(const std::vector<double>& lengths,
                                                     const std::vector<double>& turning) {
  const std::size_t n = lengths.size();
  double sum = 0, total = 0;
  for (double a : turning) sum += a;
  for (double l : lengths) total += l;
  if (!(sum > 1e-9) || !(total > 0) || turning.size() != n) return std::nullopt;
  const double scale = 2 * M_PI / sum;
  std::vector<Vec2> p(n);
  Vec2 at(0);
  double dir = 0, run = 0;
  for (std::size_t k = 0; k < n; ++k) {
    at += lengths[k] * Vec2(std::cos(dir), std::sin(dir));
    p[k] = at;
    dir += scale * turning[k];
  }
  // p[n-1] should be the start (0, 0): spread the gap over the edges by arc length.
  const Vec2 gap = p[n - 1];
  for (std::size_t k = 0; k < n; ++k) {
    run += lengths[k];
    p[k] -= gap * (run / total);
  }
  fit_unit_box(p);
  return p;
}

}  // namespace pl
