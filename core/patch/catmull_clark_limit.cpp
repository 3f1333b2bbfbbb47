#include "core/patch/catmull_clark_limit.hpp"

#include <opensubdiv/far/patchMap.h>
#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/ptexIndices.h>
#include <opensubdiv/far/stencilTableFactory.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>

namespace pl {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

struct CatmullClarkLimit::Osd {
  OpenMesh::PolyMesh_ArrayKernelT<> mesh;  // the control mesh topology
  std::unique_ptr<Far::TopologyRefiner> refiner;
  std::unique_ptr<Far::PatchTable> patches;
  std::unique_ptr<Far::PatchMap> map;
  // Stencils from the base vertices to every refined vertex and local (end-cap) point, indexed
  // like the patch table's point indices.
  std::unique_ptr<const Far::StencilTableReal<double>> stencils;
};

CatmullClarkLimit::CatmullClarkLimit(std::size_t n, const std::vector<std::vector<int>>& faces)
    : vertex_count_(n), faces_(faces), osd_(std::make_unique<Osd>()) {
  if (faces_.empty()) throw std::invalid_argument("a Catmull-Clark mesh needs at least one face");
  std::vector<int> used(n, 0);
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    if (faces_[f].size() < 3)
      throw std::invalid_argument("face " + std::to_string(f) + " has " +
                                  std::to_string(faces_[f].size()) +
                                  " vertices: a face needs at least 3");
    for (int v : faces_[f]) {
      if (v < 0 || static_cast<std::size_t>(v) >= n)
        throw std::invalid_argument("face " + std::to_string(f) + ": vertex " + std::to_string(v) +
                                    " does not exist (" + std::to_string(n) + " vertices)");
      ++used[v];
    }
  }
  for (std::size_t v = 0; v < n; ++v)
    if (!used[v])
      throw std::invalid_argument("vertex " + std::to_string(v) + " is used by no face");
  // OpenMesh refuses non-manifold and inconsistently oriented faces (add_face fails).
  auto& mesh = osd_->mesh;
  std::vector<OpenMesh::VertexHandle> vh(n);
  for (std::size_t v = 0; v < n; ++v) vh[v] = mesh.add_vertex({0, 0, 0});
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    std::vector<OpenMesh::VertexHandle> loop;
    for (int v : faces_[f]) loop.push_back(vh[v]);
    if (!mesh.add_face(loop).is_valid())
      throw std::invalid_argument("face " + std::to_string(f) +
                                  " makes the mesh non-manifold or flips its orientation");
  }

  std::vector<int> counts, indices;
  for (const auto& f : faces_) {
    counts.push_back(static_cast<int>(f.size()));
    indices.insert(indices.end(), f.begin(), f.end());
  }
  Far::TopologyDescriptor desc;
  desc.numVertices = static_cast<int>(n);
  desc.numFaces = static_cast<int>(faces_.size());
  desc.numVertsPerFace = counts.data();
  desc.vertIndicesPerFace = indices.data();
  Sdc::Options sdc;
  sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  osd_->refiner.reset(Factory::Create(desc, Factory::Options(Sdc::SCHEME_CATMARK, sdc)));
  if (!osd_->refiner) throw std::invalid_argument("OpenSubdiv rejected the control mesh topology");
  // Catmull-Clark quadrangulates non-quad faces: n ptex faces each, consecutive per face.
  const Far::PtexIndices ptex(*osd_->refiner);
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    const std::size_t sub = faces_[f].size() == 4 ? 1 : faces_[f].size();
    if (ptex.GetFaceId(static_cast<int>(f)) != static_cast<int>(ptex_face_.size()))
      throw std::logic_error("OpenSubdiv numbered ptex faces out of face order");
    ptex_face_.insert(ptex_face_.end(), sub, static_cast<int>(f));
  }

  Far::PatchTableFactory::Options po(10);
  po.SetEndCapType(Far::PatchTableFactory::Options::ENDCAP_GREGORY_BASIS);
  po.useInfSharpPatch = true;
  po.patchPrecisionDouble = true;
  osd_->refiner->RefineAdaptive(po.GetRefineAdaptiveOptions());
  osd_->patches.reset(Far::PatchTableFactory::Create(*osd_->refiner, po));
  osd_->map = std::make_unique<Far::PatchMap>(*osd_->patches);

  using StencilFactory = Far::StencilTableFactoryReal<double>;
  StencilFactory::Options so;
  so.generateIntermediateLevels = true;
  so.generateOffsets = true;
  so.generateControlVerts = true;  // stencil i is point i of the patch table
  std::unique_ptr<const Far::StencilTableReal<double>> refined(
      StencilFactory::Create(*osd_->refiner, so));
  if (const auto* local = osd_->patches->GetLocalPointStencilTable<double>()) {
    osd_->stencils.reset(
        StencilFactory::AppendLocalPointStencilTable(*osd_->refiner, refined.get(), local));
  } else {
    osd_->stencils = std::move(refined);
  }
}

CatmullClarkLimit::~CatmullClarkLimit() = default;

bool CatmullClarkLimit::boundary_vertex(int v) const {
  return osd_->mesh.is_boundary(OpenMesh::VertexHandle(v));
}

std::vector<std::pair<int, Jet>> CatmullClarkLimit::basis(int ptex, Vec2 uv) const {
  // Points outside the face (finite differences at its border) use the face's own patch there.
  const double u = std::clamp(uv.x, 0.0, 1.0), v = std::clamp(uv.y, 0.0, 1.0);
  const Far::PatchTable::PatchHandle* h = osd_->map->FindPatch(ptex, u, v);
  if (!h) throw std::logic_error("OpenSubdiv found no patch for a face parameter");
  double w[20], wu[20], wv[20], wuu[20], wuv[20], wvv[20];
  osd_->patches->EvaluateBasis(*h, uv.x, uv.y, w, wu, wv, wuu, wuv, wvv);
  // Patches under a non-quad face's sub-face: EvaluateBasis scales derivatives by 2^depth, but
  // the ptex (u, v) of a sub-face spans 2^(depth-1) patches (PatchParam::GetParamFraction), so
  // its derivatives come out twice too large per order (checked against finite differences in
  // the tests). Scaled back to the ptex face's own (u, v).
  if (osd_->patches->GetPatchParam(*h).NonQuadRoot())
    for (int i = 0; i < 20; ++i)
      wu[i] *= 0.5, wv[i] *= 0.5, wuu[i] *= 0.25, wuv[i] *= 0.25, wvv[i] *= 0.25;
  const Far::ConstIndexArray cvs = osd_->patches->GetPatchVertices(*h);
  std::map<int, Jet> acc;
  for (int i = 0; i < cvs.size(); ++i) {
    const Jet wi(w[i], wu[i], wv[i], wuu[i], wuv[i], wvv[i]);
    const auto s = osd_->stencils->GetStencil(cvs[i]);
    const int* idx = s.GetVertexIndices();
    const double* sw = s.GetWeights();
    for (int k = 0; k < s.GetSize(); ++k) acc[idx[k]] += wi * sw[k];
  }
  return {acc.begin(), acc.end()};
}

Vec3 CatmullClarkLimit::limit_point(int ptex, Vec2 uv, const std::vector<Vec3>& points) const {
  using Factory = Far::LimitStencilTableFactoryReal<double>;
  const double s = std::clamp(uv.x, 0.0, 1.0), t = std::clamp(uv.y, 0.0, 1.0);
  Factory::LocationArray loc;
  loc.ptexIdx = ptex;
  loc.numLocations = 1;
  loc.s = &s;
  loc.t = &t;
  Factory::Options lo;
  lo.generate1stDerivatives = false;
  lo.generate2ndDerivatives = false;
  // The refined-vertex stencils and patch table are shared (they define the surface); the rest
  // of the evaluation is OpenSubdiv's.
  std::unique_ptr<const Far::LimitStencilTableReal<double>> table(
      Factory::Create(*osd_->refiner, {loc}, osd_->stencils.get(), osd_->patches.get(), lo));
  if (!table || table->GetNumStencils() != 1)
    throw std::logic_error("OpenSubdiv made no limit stencil for a face parameter");
  const auto st = table->GetLimitStencil(0);
  Vec3 p(0);
  for (int k = 0; k < st.GetSize(); ++k)
    p += st.GetWeights()[k] * points.at(st.GetVertexIndices()[k]);
  return p;
}

}  // namespace pl
