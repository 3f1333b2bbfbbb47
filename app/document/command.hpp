// Every edit is a command on the document. UI code never mutates geometry
// directly. Undo does not invert a command: the document keeps the scene before and after it
// (patches are shared and copied on write, so that is cheap), which makes undo bit-exact even
// where a command moves several things at once.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "app/document/point_ref.hpp"

namespace pl {

class Command {
 public:
  virtual ~Command() = default;
  virtual void apply(Scene& scene) const = 0;
  virtual std::string label() const = 0;
};

// Moves points to new positions (a typed coordinate, a nudge; drags go through the document).
class MovePointsCommand final : public Command {
 public:
  MovePointsCommand(std::vector<PointRef> refs, std::vector<Vec3> positions);
  void apply(Scene& scene) const override;
  std::string label() const override;
  const std::vector<PointRef>& refs() const { return refs_; }

 private:
  std::vector<PointRef> refs_;
  std::vector<Vec3> positions_;
};

// Sets a network face's filling scheme.
class SetFaceSchemeCommand final : public Command {
 public:
  SetFaceSchemeCommand(int face, FaceScheme scheme) : face_(face), scheme_(scheme) {}
  void apply(Scene& scene) const override { scene.network->faces.at(face_).scheme = scheme_; }
  std::string label() const override { return "change scheme of face " + std::to_string(face_); }

 private:
  int face_;
  FaceScheme scheme_;
};

}  // namespace pl
