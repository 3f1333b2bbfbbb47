#include "core/io/scene_io.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/io/atomic_file.hpp"
#include "core/io/curve_codec.hpp"
#include "core/io/input_limits.hpp"
#include "core/io/json_node.hpp"
#include "core/io/patch_codec.hpp"
#include "core/io/scene_checks.hpp"
#include "core/patch/gb/default_net.hpp"
#include "core/scene/network_edit.hpp"

namespace pl {

namespace {

FaceScheme read_scheme(const JsonNode& node, int sides) {
  const std::string s = node.string();
  const std::optional<FaceScheme> scheme = parse_scheme_keyword(s);
  if (!scheme)
    node.fail("unknown scheme \"" + s + "\" (allowed: auto, " + face_scheme_keywords() + ")");
  if (*scheme == FaceScheme::Gregory && sides != 3 && sides != 4)
    node.fail("scheme \"gregory\" needs a face of 3 or 4 sides, this one has " +
              std::to_string(sides));
  return *scheme;
}

// The stored index of a free point in the face's .gbp net: two names of one shared corner-block
// point get the same key (0 for the central point).
std::size_t offset_key(int sides, int degree, const InteriorOffset& o) {
  return o.centre ? 0 : gb_net_index(sides, degree, o.side, o.j, o.layer);
}

// "degree" and "offsets" of face f (docs/scene-format.md, "Interior control").
void read_interior(const JsonNode& f, NetworkFace& face) {
  const auto degree = f.find("degree");
  const auto offsets = f.find("offsets");
  if (!degree && !offsets) return;
  const int n = static_cast<int>(face.loop.size());
  if (resolve_scheme(face, std::nullopt) != FaceScheme::GB)
    (degree ? *degree : *offsets)
        .fail(
            "a Gregory face has no free interior (all its inner points are G1 data); degree "
            "and offsets need scheme \"gb\" (or a face of 5 or more sides)");
  if (degree) face.degree = degree->integer_in(3, kMaxGBFaceDegree);
  if (!offsets) return;
  std::set<std::size_t> seen;
  for (const JsonNode& o : offsets->items()) {
    o.allow_only({"at", "by"});
    InteriorOffset off;
    const JsonNode at = o.at("at");
    if (at.raw().is_string()) {
      if (at.string() != "center") at.fail("expected \"center\" or [side, j, layer]");
      off.centre = true;
    } else {
      const auto ijk = at.items(3);
      off.side = static_cast<int>(ijk[0].integer());
      off.j = static_cast<int>(ijk[1].integer());
      off.layer = static_cast<int>(ijk[2].integer());
      if (const std::string why = interior_offset_problem(n, face.degree, off); !why.empty())
        at.fail(why);
    }
    if (!seen.insert(offset_key(n, face.degree, off)).second)
      at.fail("this point already has an offset (a shared corner point has two names)");
    off.by = o.at("by").point();
    face.offsets.push_back(off);
  }
}

nlohmann::json interior_offsets_json(const std::vector<InteriorOffset>& offsets) {
  nlohmann::json out = nlohmann::json::array();
  for (const InteriorOffset& o : offsets)
    out.push_back({{"at", o.centre ? nlohmann::json("center")
                                   : nlohmann::json::array({o.side, o.j, o.layer})},
                   {"by", point_json(o.by)}});
  return out;
}

Network read_network(const JsonNode& node) {
  node.allow_only({"vertices", "normals", "edges", "faces"});
  Network net;
  if (auto v = node.find("vertices")) net.vertices = v->points();
  const int nv = static_cast<int>(net.vertices.size());
  if (auto normals = node.find("normals")) {
    for (const JsonNode& n : normals->items(net.vertices.size())) {
      if (n.is_null()) {
        net.normals.emplace_back();
        continue;
      }
      const Vec3 v = n.point();
      if (glm::length(v) == 0) n.fail("a normal must not be the zero vector");
      net.normals.emplace_back(stored_normal(v));  // as the editor stores them: a fixed point
    }
  }
  if (auto edges = node.find("edges"))
    for (const JsonNode& e : edges->items()) {
      e.allow_only({"v", "handles", "name"});
      NetworkEdge ed;
      const auto v = e.at("v").items(2);
      for (int k = 0; k < 2; ++k) ed.v[k] = v[k].integer_in(0, nv > 0 ? nv - 1 : -1);
      const auto h = e.at("handles").items(2);
      ed.handles = {h[0].point(), h[1].point()};
      if (auto name = e.find("name")) ed.name = name->string();
      net.edges.push_back(std::move(ed));
    }
  if (auto faces = node.find("faces"))
    for (const JsonNode& f : faces->items()) {
      f.allow_only({"loop", "scheme", "name", "degree", "offsets", "fullness"});
      NetworkFace face;
      const JsonNode loop = f.at("loop");
      if (loop.items().size() > std::size_t(kMaxFaceSides))
        loop.fail("a face has at most " + std::to_string(kMaxFaceSides) + " sides, this one has " +
                  std::to_string(loop.items().size()));
      for (const JsonNode& i : loop.items()) {
        const long long idx = i.integer();
        if (idx < 0 || idx >= nv)
          i.fail("vertex " + std::to_string(idx) + " does not exist (" + std::to_string(nv) +
                 " vertices)");
        face.loop.push_back(static_cast<int>(idx));
      }
      if (auto s = f.find("scheme"))
        face.scheme = read_scheme(*s, static_cast<int>(face.loop.size()));
      if (auto name = f.find("name")) face.name = name->string();
      if (auto full = f.find("fullness")) {
        if (face.scheme != FaceScheme::Midpoint && face.scheme != FaceScheme::MidpointCoons)
          full->fail("fullness is a setting of the midpoint and midpoint-coons schemes");
        face.fullness = full->number();
        if (std::abs(face.fullness) > 100) full->fail("the fullness lies in [-100, 100]");
      }
      read_interior(f, face);
      net.faces.push_back(std::move(face));
    }
  return net;
}

ScenePatch read_patch(const JsonNode& node) {
  node.require_object();
  const JsonNode type = node.at("type");
  const std::string t = type.string();
  const PatchCodec* codec = find_patch_codec(t);
  if (!codec) {
    std::string known;
    for (const PatchCodec& c : patch_codecs())
      known += std::string(known.empty() ? "" : ", ") + c.type;
    type.fail("unknown patch type \"" + t + "\" (known: " + known + ")");
  }
  ScenePatch sp;
  if (auto name = node.find("name")) sp.name = name->string();
  try {
    sp.patch = codec->read(node);
  } catch (const std::invalid_argument& e) {  // a constructor rejected the data
    node.fail(e.what());
  }
  return sp;
}

// Item `index` of the scene's "curves".
SceneCurve read_scene_curve(const nlohmann::json& item, std::size_t index,
                            const std::string& source, std::vector<Vec3>* packed_points) {
  const JsonNode node(item, source, "curves[" + std::to_string(index) + "]");
  SceneCurve c = read_curve(node, packed_points);
  // A curve shrunk to a point has no tangent or curvature (a Hermite curve may start and end at
  // one point: its tangents give it extent).
  if (c.type != CurveType::Hermite) check_span(c.points, source, node.path() + ".points");
  return c;
}

}  // namespace

Scene parse_scene(const std::string& text, const std::string& source) {
  // The curves are read as the parser meets them, without their JSON kept; the first one that
  // fails is reported when the curves' turn comes below, after the checks of everything before
  // them (and after any syntax error), as when the whole document was read first.
  std::vector<SceneCurve> curves;
  std::exception_ptr curve_error;
  const auto read = [&](const nlohmann::json& item, std::size_t index, std::vector<Vec3>* packed) {
    if (curve_error) return;
    try {
      curves.push_back(read_scene_curve(item, index, source, packed));
    } catch (...) {
      curve_error = std::current_exception();
    }
  };
  const StreamedArray streamed{"curves", read, "points"};
  const nlohmann::json doc = parse_json(text, source, streamed);
  const JsonNode root(doc, source);
  root.require_object();
  const JsonNode version = root.at("patchlab");
  if (!version.raw().is_number_integer() || version.raw().get<long long>() != 1)
    version.fail("unsupported format version " + version.raw().dump() + " (this reader knows 1)");
  root.allow_only({"patchlab", "name", "network", "patches", "curves", "view"});
  Scene scene;
  if (auto name = root.find("name")) scene.name = name->string();
  if (auto net = root.find("network")) {
    scene.network = read_network(*net);
    check_face_loops(*scene.network, validate_network(*scene.network, source), source);
  }
  if (auto patches = root.find("patches"))
    for (const JsonNode& p : patches->items()) scene.patches.push_back(read_patch(p));
  if (auto node = root.find("curves")) {
    node->size();  // an array (anything else stayed in the document and is refused here)
    if (curve_error) std::rethrow_exception(curve_error);
    scene.curves = std::move(curves);
  }
  check_spans(scene, source);
  if (auto view = root.find("view")) {
    view->require_object();
    scene.view_json = view->raw().dump();
  }
  return scene;
}

Scene read_scene(const std::filesystem::path& path) {
  return parse_scene(read_text_file(path), path.string());
}

namespace {

// The writer's key order (docs/scene-files.md): the order of the format's description, which
// every shipped sample follows, so a scene loaded and saved again differs from a hand-written
// file only where it was edited. nlohmann::json keeps keys sorted; the file is built as an
// ordered_json instead.
using Ordered = nlohmann::ordered_json;

// The keys of a patch object other than "type" and "name", which come first. A key not listed
// (a new codec's) follows the listed ones, in alphabetical order.
constexpr const char* kPatchKeyOrder[] = {
    "sides", "order",   "degree",  "layers", "aux_degree", "size",     "knots_u", "knots_v", "s",
    "t",     "domain",  "ribbons", "q",      "r",          "vertices", "faces",   "points",  "aux",
    "data",  "weights", "lengths", "a",      "b",          "b1",       "c1",      "b2",      "c2"};

int patch_key_rank(const std::string& key) {
  int rank = 0;
  for (const char* k : kPatchKeyOrder) {
    if (key == k) return rank;
    ++rank;
  }
  return rank;  // after every listed key; ties keep nlohmann::json's alphabetical order
}

// A codec's output in the writer's order, recursively (gap-fill and pair-join nest objects).
Ordered ordered(const nlohmann::json& j) {
  if (j.is_object()) {
    std::vector<std::pair<std::string, const nlohmann::json*>> items;
    for (auto it = j.begin(); it != j.end(); ++it) items.emplace_back(it.key(), &it.value());
    std::stable_sort(items.begin(), items.end(), [](const auto& a, const auto& b) {
      return patch_key_rank(a.first) < patch_key_rank(b.first);
    });
    Ordered o = Ordered::object();
    for (const auto& [key, value] : items) o[key] = ordered(*value);
    return o;
  }
  if (j.is_array()) {
    Ordered a = Ordered::array();
    for (const nlohmann::json& x : j) a.push_back(ordered(x));
    return a;
  }
  return Ordered(j);
}

// The document but for its curves: with curves, an empty "curves" array holds their place.
Ordered document_without_curves(const Scene& scene) {
  Ordered doc = Ordered::object();
  doc["patchlab"] = 1;
  if (!scene.name.empty()) doc["name"] = scene.name;
  if (scene.network) {
    const Network& n = *scene.network;
    Ordered net = Ordered::object();
    net["vertices"] = ordered(points_json(n.vertices));
    if (!n.normals.empty()) {
      Ordered normals = Ordered::array();
      for (const auto& v : n.normals) normals.push_back(v ? ordered(point_json(*v)) : Ordered());
      net["normals"] = normals;
    }
    net["edges"] = Ordered::array();
    for (const NetworkEdge& e : n.edges) {
      Ordered je = Ordered::object();
      je["v"] = {e.v[0], e.v[1]};
      je["handles"] = {ordered(point_json(e.handles[0])), ordered(point_json(e.handles[1]))};
      if (!e.name.empty()) je["name"] = e.name;
      net["edges"].push_back(je);
    }
    net["faces"] = Ordered::array();
    for (const NetworkFace& f : n.faces) {
      Ordered jf = Ordered::object();
      jf["loop"] = f.loop;
      if (f.scheme != FaceScheme::Auto) jf["scheme"] = scheme_keyword(f.scheme);
      if (!f.name.empty()) jf["name"] = f.name;
      if (f.degree != 3) jf["degree"] = f.degree;
      if (f.fullness != 1) jf["fullness"] = f.fullness;
      if (!f.offsets.empty()) jf["offsets"] = interior_offsets_json(f.offsets);
      net["faces"].push_back(jf);
    }
    doc["network"] = net;
  }
  if (!scene.patches.empty()) {
    doc["patches"] = Ordered::array();
    for (const ScenePatch& sp : scene.patches) {
      const PatchCodec* codec = find_patch_codec(sp.patch->type());
      // Every patch type registers a codec (core/io/patch_codecs.cpp); a missing one is a
      // programming error, reported rather than dereferenced.
      if (!codec) throw std::logic_error("no scene codec for patch type " + sp.patch->type());
      nlohmann::json body;
      codec->write(*sp.patch, body);
      Ordered jp = Ordered::object();
      jp["type"] = sp.patch->type();
      if (!sp.name.empty()) jp["name"] = sp.name;
      Ordered keys = ordered(body);
      for (auto& [key, value] : keys.items()) jp[key] = std::move(value);
      doc["patches"].push_back(jp);
    }
  }
  if (!scene.curves.empty()) doc["curves"] = Ordered::array();
  // The editor's view object as the reader kept it (its keys sorted: it is free-form).
  if (!scene.view_json.empty()) doc["view"] = Ordered::parse(scene.view_json);
  return doc;
}

// `text` (a value dumped at depth 0, indent 1) as it reads at `depth`: one more space per level
// after each line break. A dumped value has no line break but the writer's (strings escape theirs).
void append_at_depth(std::string& out, const std::string& text, int depth) {
  out.reserve(out.size() + text.size() + depth * std::count(text.begin(), text.end(), '\n'));
  for (const char ch : text) {
    out += ch;
    if (ch == '\n') out.append(depth, ' ');
  }
}

// An array of n items as dump(1) writes it at `depth`; `item(i)` is the text of item i dumped at
// depth 0. `flush` is offered the text after every item.
template <class Item, class Flush>
void append_array(std::string& out, std::size_t n, int depth, Item&& item, Flush&& flush) {
  if (n == 0) {
    out += "[]";
    return;
  }
  out += '[';
  for (std::size_t i = 0; i < n; ++i) {
    out += i ? ",\n" : "\n";
    out.append(depth + 1, ' ');
    append_at_depth(out, item(i), depth + 1);
    flush(out);
  }
  out += '\n';
  out.append(depth, ' ');
  out += ']';
}

// A curve object as dump(1) writes it at `depth`, its keys in the format's order, its arrays
// written item by item from the curve (nlohmann's text for every number), handed to `flush` as
// they grow: one curve may be the whole scene.
template <class Flush>
void append_curve(std::string& out, const SceneCurve& c, int depth, Flush&& flush) {
  out += '{';
  bool first = true;
  for (const CurveKey& k : curve_keys(c)) {
    out += first ? "\n" : ",\n";
    first = false;
    out.append(depth + 1, ' ');
    out += '"';
    out += k.key;
    out += "\": ";
    if (k.points)
      append_array(
          out, k.points->size(), depth + 1,
          [&](std::size_t i) {
            const Vec3& p = (*k.points)[i];
            return nlohmann::json{p.x, p.y, p.z}.dump(1);
          },
          flush);
    else if (k.numbers)
      append_array(
          out, k.numbers->size(), depth + 1,
          [&](std::size_t i) { return nlohmann::json((*k.numbers)[i]).dump(1); }, flush);
    else
      append_at_depth(out, k.value.dump(1), depth + 1);
  }
  out += '\n';
  out.append(depth, ' ');
  out += '}';
}

// The text of the document (one space of indent a level, as nlohmann's dump(1) writes it), in
// pieces of about a megabyte: everything but the curves at once, then the curves. A document of
// 400,000 curves built whole took half a gigabyte (a map per object, a node per number) before
// the first byte was written.
void write_scene_text(const Scene& scene, const TextSink& write) {
  const std::string text = document_without_curves(scene).dump(1);
  const std::string place = "\n \"curves\": []";  // only the top level has keys at one space
  const std::size_t at = scene.curves.empty() ? std::string::npos : text.find(place);
  if (at == std::string::npos) {
    write(text + "\n");
    return;
  }
  const auto flush = [&](std::string& piece) {
    if (piece.size() >= (1 << 20)) write(piece), piece.clear();
  };
  std::string piece = text.substr(0, at) + "\n \"curves\": [\n";
  for (std::size_t i = 0; i < scene.curves.size(); ++i) {
    piece += "  ";
    append_curve(piece, scene.curves[i], 2, flush);
    piece += i + 1 < scene.curves.size() ? ",\n" : "\n";
    flush(piece);
  }
  piece += " ]";
  piece.append(text, at + place.size());
  write(piece + "\n");
}

}  // namespace

std::string scene_to_json(const Scene& scene) {
  std::string out;
  write_scene_text(scene, [&](std::string_view piece) { out += piece; });
  return out;
}

void write_scene(const std::filesystem::path& path, const Scene& scene) {
  write_text_atomically(path, [&](const TextSink& write) { write_scene_text(scene, write); });
}

}  // namespace pl
