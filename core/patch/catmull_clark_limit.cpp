#include "core/patch/catmull_clark_limit.hpp"

#include <opensubdiv/far/patchMap.h>
#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/ptexIndices.h>
#include <opensubdiv/far/stencilTableFactory.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <algorithm>
#include <array>
#include <set>
#include <stdexcept>
#include <string>

namespace pl {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

namespace {

// A stencil table made from our own arrays (its constructor is protected: only OpenSubdiv's
// factories build them).
class OwnStencilTable final : public Far::StencilTableReal<double> {
 public:
  OwnStencilTable(int control_vertices, const std::vector<int>& offsets,
                  const std::vector<int>& sizes, const std::vector<int>& sources,
                  const std::vector<double>& weights)
      // Every stencil, the control vertices' included: after those the copy resumes at
      // firstOffset, which is where the rest begins.
      : Far::StencilTableReal<double>(control_vertices, offsets, sizes, sources, weights, true,
                                      static_cast<std::size_t>(control_vertices)) {}
};

// A stencil while it is built: (base vertex, weight) entries, appended by the refiner and
// merged by a Merger.
struct StencilBuild {
  std::vector<std::pair<int, double>> e;
  void Clear(void* = nullptr) { e.clear(); }
  void AddWithWeight(const StencilBuild& s, double w) {
    for (const auto& [v, x] : s.e) e.emplace_back(v, x * w);
  }
};

// Merges entries by vertex through a dense row over the base vertices: O(entries), where
// sorting the appended entries (16 parents of n entries each near an n-ring) cost a log factor
// and most of the construction.
class Merger {
 public:
  explicit Merger(std::size_t vertices) : row_(vertices, 0.0), seen_(vertices, 0) {}
  void add(int v, double w) {
    if (!seen_[v]) seen_[v] = 1, touched_.push_back(v);
    row_[v] += w;
  }
  // The merged stencil, vertices ascending; the row is clean again.
  void take(StencilBuild& out) {
    std::sort(touched_.begin(), touched_.end());
    out.e.clear();
    out.e.shrink_to_fit();  // the appended entries were many times the merged ones
    out.e.reserve(touched_.size());
    for (const int v : touched_) {
      out.e.emplace_back(v, row_[v]);
      row_[v] = 0, seen_[v] = 0;
    }
    touched_.clear();
  }

 private:
  std::vector<double> row_;
  std::vector<char> seen_;
  std::vector<int> touched_;
};

// A block of kBlock consecutive base vertices' weights in one vertex: the primvar with which
// the refiner interpolates kBlock columns of the stencil matrix at once.
constexpr int kBlock = 64;
struct WeightBlock {
  std::array<double, kBlock> w;
  void Clear(void* = nullptr) { w.fill(0.0); }
  void AddWithWeight(const WeightBlock& s, double x) {
    for (int k = 0; k < kBlock; ++k) w[k] += x * s.w[k];
  }
};

// Dense columns cost base vertices x refined vertices; sparse rows cost the stencils' entries
// times the refiner's fan-in, which near an n-ring is n per vertex at every isolation level.
// Below this product the columns are taken (it bounds their time to about a second).
constexpr double kMaxDenseWork = 4e8;

}  // namespace

struct CatmullClarkLimit::Osd {
  OpenMesh::PolyMesh_ArrayKernelT<> mesh;  // the control mesh topology
  std::unique_ptr<Far::TopologyRefiner> refiner;
  std::unique_ptr<Far::PatchTable> patches;
  std::unique_ptr<Far::PatchMap> map;
  // Stencils from the base vertices to every vertex of every level and every local (end-cap)
  // point, indexed like the patch table's point indices; vertices ascending within each.
  std::unique_ptr<const Far::StencilTableReal<double>> stencils;
};

namespace {

std::string face_name(std::size_t f) {
  return "face " + std::to_string(f);
}

// The rules OpenMesh and OpenSubdiv assume (OpenMesh aborts on a repeated vertex, and prints its
// own complaints), and the limits that keep the work bounded, checked before either sees the mesh.
void check_mesh(std::size_t n, const std::vector<std::vector<int>>& faces) {
  if (faces.empty()) throw std::invalid_argument("a Catmull-Clark mesh needs at least one face");
  if (n > CatmullClarkLimit::kMaxVertices)
    throw std::invalid_argument("the mesh has " + std::to_string(n) + " vertices; at most " +
                                std::to_string(CatmullClarkLimit::kMaxVertices) + " are supported");
  std::vector<int> valence(n, 0);
  std::set<std::pair<int, int>> directed;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const auto& loop = faces[f];
    if (loop.size() < 3)
      throw std::invalid_argument(face_name(f) + " has " + std::to_string(loop.size()) +
                                  " vertices: a face needs at least 3");
    if (loop.size() > std::size_t(CatmullClarkLimit::kMaxValence))
      throw std::invalid_argument(
          face_name(f) + " has " + std::to_string(loop.size()) + " vertices; at most " +
          std::to_string(CatmullClarkLimit::kMaxValence) + " are supported");
    for (int v : loop)
      if (v < 0 || static_cast<std::size_t>(v) >= n)
        throw std::invalid_argument(face_name(f) + ": vertex " + std::to_string(v) +
                                    " does not exist (" + std::to_string(n) + " vertices)");
    std::vector<int> sorted = loop;
    std::sort(sorted.begin(), sorted.end());
    const auto repeat = std::adjacent_find(sorted.begin(), sorted.end());
    if (repeat != sorted.end())
      throw std::invalid_argument(face_name(f) + " repeats vertex " + std::to_string(*repeat) +
                                  ": a face's vertices must be distinct");
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const int a = loop[i], b = loop[(i + 1) % loop.size()];
      if (!directed.insert({a, b}).second)
        throw std::invalid_argument(face_name(f) + ": the edge from vertex " + std::to_string(a) +
                                    " to " + std::to_string(b) +
                                    " is used twice in this direction (the faces on it are "
                                    "flipped, or more than two faces share it)");
      if (++valence[a] > CatmullClarkLimit::kMaxValence)
        throw std::invalid_argument("vertex " + std::to_string(a) + " is in more than " +
                                    std::to_string(CatmullClarkLimit::kMaxValence) + " faces");
    }
  }
  for (std::size_t v = 0; v < n; ++v)
    if (!valence[v])
      throw std::invalid_argument("vertex " + std::to_string(v) + " is used by no face");
}

}  // namespace

CatmullClarkLimit::CatmullClarkLimit(std::size_t n, const std::vector<std::vector<int>>& faces)
    : vertex_count_(n), faces_(faces), osd_(std::make_unique<Osd>()) {
  check_mesh(n, faces_);
  // OpenMesh refuses what is left (faces that touch at a vertex only: a non-manifold vertex),
  // saying so on its error stream: the message is ours.
  auto& mesh = osd_->mesh;
  std::vector<OpenMesh::VertexHandle> vh(n);
  for (std::size_t v = 0; v < n; ++v) vh[v] = mesh.add_vertex({0, 0, 0});
  omerr().disable();
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    std::vector<OpenMesh::VertexHandle> loop;
    for (int v : faces_[f]) loop.push_back(vh[v]);
    if (!mesh.add_face(loop).is_valid()) {
      omerr().enable();
      throw std::invalid_argument(face_name(f) +
                                  " makes the mesh non-manifold (faces that meet at a vertex "
                                  "must be joined by edges around it)");
    }
  }
  omerr().enable();

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

  build_stencils();

  // Every patch's points as indices into its ptex face's point list.
  const Far::PatchTable& table = *osd_->patches;
  face_points_.resize(ptex_face_.size());
  int total = 0;
  for (int a = 0; a < table.GetNumPatchArrays(); ++a) total += table.GetNumPatches(a);
  std::vector<int> patch_face(total);
  for (int a = 0, p = 0; a < table.GetNumPatchArrays(); ++a)
    for (int i = 0; i < table.GetNumPatches(a); ++i, ++p) {
      const int face = table.GetPatchParam(a, i).GetFaceId();
      patch_face[p] = face;
      const auto cvs = table.GetPatchVertices(a, i);
      face_points_.at(face).insert(face_points_[face].end(), cvs.begin(), cvs.end());
    }
  for (auto& fp : face_points_) {
    std::sort(fp.begin(), fp.end());
    fp.erase(std::unique(fp.begin(), fp.end()), fp.end());
  }
  patch_local_offset_.assign(1, 0);
  for (int a = 0, p = 0; a < table.GetNumPatchArrays(); ++a)
    for (int i = 0; i < table.GetNumPatches(a); ++i, ++p) {
      const auto& fp = face_points_[patch_face[p]];
      for (const int cv : table.GetPatchVertices(a, i))
        patch_local_.push_back(
            static_cast<int>(std::lower_bound(fp.begin(), fp.end(), cv) - fp.begin()));
      patch_local_offset_.push_back(static_cast<int>(patch_local_.size()));
    }
}

// OpenSubdiv's StencilTableFactory merges each added weight by a linear search through the
// stencil being built: next to an n-valent vertex, where every stencil holds the whole ring,
// that is O(n^2) per vertex and O(n^3) in all (6 s for a 256-gon). Two ways instead, both
// linear in what they produce:
// - sparse rows: every level interpolated with stencils as the primvar, merged once through a
//   dense row: O(entries x fan-in). Near an n-ring every isolated vertex's stencil holds the
//   ring, at every one of the 10 levels, around every feature the ring touches (a valence-200
//   fan: 80,000 vertices of ~190 entries, 15 million entries made from ten times as many
//   appended ones: seconds);
// - dense columns: kBlock base vertices at a time, their unit weights interpolated as a
//   kBlock-wide primvar through every level (and the end-cap points), the non-zeros appended to
//   the stencils in vertex order: O(base vertices x refined vertices), arithmetic only. For
//   the small meshes that hold a big ring (the fan: 201 x 80,000) this is a hundred times less.
// The cheaper by those counts is taken. Both give the same stencils (the same sums, up to
// rounding); a weight that sums to exactly zero is left out of a dense column.
void CatmullClarkLimit::build_stencils() {
  const Far::TopologyRefiner& r = *osd_->refiner;
  const int base = r.GetLevel(0).GetNumVertices();
  const Far::StencilTableReal<double>* local = osd_->patches->GetLocalPointStencilTable<double>();
  const std::size_t refined = r.GetNumVerticesTotal();
  const std::size_t total = refined + (local ? local->GetNumStencils() : 0);
  const Far::PrimvarRefinerReal<double> primvar(r);
  std::vector<int> offsets(total), sizes(total, 0), sources;
  std::vector<double> weights;
  if (double(base) * double(refined) <= kMaxDenseWork) {
    // Twice through the blocks: the non-zeros counted, then written in place (appending to
    // growing stencils, block after block, spent more time in the allocator than in the sums).
    std::vector<WeightBlock> col(refined);
    std::vector<int> fill;
    for (int pass = 0; pass < 2; ++pass) {
      if (pass == 1) {
        std::size_t at = 0;
        for (std::size_t v = 0; v < total; ++v) offsets[v] = static_cast<int>(at), at += sizes[v];
        sources.resize(at);
        weights.resize(at);
        fill = offsets;
      }
      for (int j0 = 0; j0 < base; j0 += kBlock) {
        const int nb = std::min(kBlock, base - j0);
        for (int v = 0; v < base; ++v) {
          col[v].Clear();
          if (v >= j0 && v < j0 + nb) col[v].w[v - j0] = 1.0;
        }
        for (int level = 1, first = 0; level <= r.GetMaxLevel(); ++level) {
          const int before = r.GetLevel(level - 1).GetNumVertices();
          WeightBlock* src = col.data() + first;
          WeightBlock* dst = src + before;
          primvar.Interpolate(level, src, dst);
          first += before;
        }
        auto emit = [&](std::size_t v, const WeightBlock& c) {
          for (int k = 0; k < nb; ++k)
            if (c.w[k] != 0.0) {
              if (pass == 0) {
                ++sizes[v];
              } else {
                sources[fill[v]] = j0 + k;
                weights[fill[v]++] = c.w[k];
              }
            }
        };
        for (std::size_t v = 0; v < refined; ++v) emit(v, col[v]);
        if (local) {
          WeightBlock acc;
          for (int i = 0; i < local->GetNumStencils(); ++i) {
            const auto st = local->GetStencil(i);
            acc.Clear();
            for (int k = 0; k < st.GetSize(); ++k)
              acc.AddWithWeight(col[st.GetVertexIndices()[k]], st.GetWeights()[k]);
            emit(refined + i, acc);
          }
        }
      }
    }
  } else {
    std::vector<StencilBuild> all(total);
    for (int v = 0; v < base; ++v) all[v].e = {{v, 1.0}};
    Merger merger(base);
    for (int level = 1, first = 0; level <= r.GetMaxLevel(); ++level) {
      const int before = r.GetLevel(level - 1).GetNumVertices();
      StencilBuild* src = all.data() + first;
      StencilBuild* dst = src + before;
      primvar.Interpolate(level, src, dst);
      for (int v = 0; v < r.GetLevel(level).GetNumVertices(); ++v) {
        for (const auto& [u, w] : dst[v].e) merger.add(u, w);
        merger.take(dst[v]);
      }
      first += before;
    }
    // End-cap points: each a stencil over the last level's vertices (an extraordinary vertex's
    // whole ring for the points at it).
    if (local)
      for (int i = 0; i < local->GetNumStencils(); ++i) {
        const auto st = local->GetStencil(i);
        for (int k = 0; k < st.GetSize(); ++k)
          for (const auto& [v, w] : all.at(st.GetVertexIndices()[k]).e)
            merger.add(v, w * st.GetWeights()[k]);
        merger.take(all[refined + i]);
      }
    for (std::size_t v = 0; v < total; ++v) {
      offsets[v] = static_cast<int>(sources.size());
      sizes[v] = static_cast<int>(all[v].e.size());
      for (const auto& [u, w] : all[v].e) sources.push_back(u), weights.push_back(w);
    }
  }
  osd_->stencils = std::make_unique<OwnStencilTable>(base, offsets, sizes, sources, weights);
}

CatmullClarkLimit::~CatmullClarkLimit() = default;

bool CatmullClarkLimit::boundary_vertex(int v) const {
  return osd_->mesh.is_boundary(OpenMesh::VertexHandle(v));
}

std::span<const int> CatmullClarkLimit::stencil_vertices(int point) const {
  const auto st = osd_->stencils->GetStencil(point);
  return {st.GetVertexIndices(), static_cast<std::size_t>(st.GetSize())};
}

std::span<const double> CatmullClarkLimit::stencil_weights(int point) const {
  const auto st = osd_->stencils->GetStencil(point);
  return {st.GetWeights(), static_cast<std::size_t>(st.GetSize())};
}

Vec3 CatmullClarkLimit::patch_point(int point, std::span<const Vec3> vertices) const {
  const auto v = stencil_vertices(point);
  const auto w = stencil_weights(point);
  std::size_t best = 0;
  for (std::size_t k = 1; k < v.size(); ++k)
    if (w[k] > w[best]) best = k;
  const Vec3 ref = vertices[v[best]];
  Vec3 p = ref;
  for (std::size_t k = 0; k < v.size(); ++k) p += w[k] * (vertices[v[k]] - ref);
  return p;
}

CatmullClarkLimit::LocalBasis CatmullClarkLimit::local_basis(int ptex, Vec2 uv) const {
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
  const double s1 = osd_->patches->GetPatchParam(*h).NonQuadRoot() ? 0.5 : 1.0, s2 = s1 * s1;
  LocalBasis b;
  const int first = patch_local_offset_.at(h->patchIndex);
  b.count = patch_local_offset_.at(h->patchIndex + 1) - first;
  for (int i = 0; i < b.count; ++i) {
    b.point[i] = patch_local_[first + i];
    b.weight[i] = Jet(w[i], wu[i] * s1, wv[i] * s1, wuu[i] * s2, wuv[i] * s2, wvv[i] * s2);
  }
  return b;
}

std::vector<std::pair<int, Jet>> CatmullClarkLimit::basis(int ptex, Vec2 uv) const {
  const LocalBasis lb = local_basis(ptex, uv);
  const auto& fp = face_points_[ptex];
  std::vector<std::pair<int, Jet>> acc;
  for (int i = 0; i < lb.count; ++i) {
    const int point = fp[lb.point[i]];
    const auto v = stencil_vertices(point);
    const auto w = stencil_weights(point);
    for (std::size_t k = 0; k < v.size(); ++k) acc.emplace_back(v[k], lb.weight[i] * w[k]);
  }
  // Merged by vertex: O(m log m) for the m stencil entries touched.
  std::stable_sort(acc.begin(), acc.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::pair<int, Jet>> out;
  for (const auto& e : acc) {
    if (!out.empty() && out.back().first == e.first)
      out.back().second += e.second;
    else
      out.push_back(e);
  }
  return out;
}

Vec3 CatmullClarkLimit::stencil_point(int ptex, Vec2 uv, std::span<const Vec3> points) const {
  const double u = std::clamp(uv.x, 0.0, 1.0), v = std::clamp(uv.y, 0.0, 1.0);
  const Far::PatchTable::PatchHandle* h = osd_->map->FindPatch(ptex, u, v);
  if (!h) throw std::logic_error("OpenSubdiv found no patch for a face parameter");
  double w[20];
  osd_->patches->EvaluateBasis(*h, u, v, w);
  const auto cvs = osd_->patches->GetPatchVertices(*h);
  Vec3 p(0);
  for (int i = 0; i < cvs.size(); ++i) {
    const auto vs = stencil_vertices(cvs[i]);
    const auto ws = stencil_weights(cvs[i]);
    for (std::size_t k = 0; k < vs.size(); ++k) p += (w[i] * ws[k]) * points[vs[k]];
  }
  return p;
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
