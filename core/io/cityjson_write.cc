#include "core/io/cityjson_write.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "base/atomic_write.h"
#include "core/geom/polygon3.h"
#include "core/io/io_error.h"
#include "core/io/output_crs.h"

namespace procex {
namespace {

using json = nlohmann::ordered_json;

constexpr double kScale = 0.001;  // millimetres
// A face within this of vertical is a wall unless its tag says otherwise.
const double kWallSlope = std::sin(10.0 * M_PI / 180.0);
// A down-facing face this close to the building's lowest point is on the ground.
constexpr double kGroundTolerance = 1e-6;

bool on_ground(const std::vector<glm::dvec3>& face, double ground) {
  return std::all_of(face.begin(), face.end(), [&](const glm::dvec3& p) { return p.z <= ground + kGroundTolerance; });
}

const char* semantic_type(const std::vector<glm::dvec3>& face, const std::string& tag, double ground) {
  const glm::dvec3 n = newell_normal(face);
  const double length = glm::length(n);
  const double up = length > 0 ? n.z / length : 0.0;
  if (up < -kWallSlope) return on_ground(face, ground) ? "GroundSurface" : "OuterCeilingSurface";
  if (tag == "wall") return "WallSurface";
  if (tag == "roof") return "RoofSurface";
  return up < kWallSlope ? "WallSurface" : "RoofSurface";
}

// The file's shared vertex list: each point quantised once.
class Vertices {
 public:
  explicit Vertices(const glm::dvec3& translate) : translate_(translate) {}
  // The index of p once quantised (equal quantised points share one).
  std::int64_t add(const glm::dvec3& p) {
    const auto q = std::make_tuple(std::llround((p.x - translate_.x) / kScale), std::llround((p.y - translate_.y) / kScale),
                                   std::llround((p.z - translate_.z) / kScale));
    const auto [it, added] = index_.try_emplace(q, static_cast<std::int64_t>(list_.size()));
    if (added) list_.push_back(json::array({std::get<0>(q), std::get<1>(q), std::get<2>(q)}));
    return it->second;
  }
  json take() { return std::move(list_); }

 private:
  glm::dvec3 translate_;
  std::map<std::tuple<long long, long long, long long>, std::int64_t> index_;
  json list_ = json::array();
};

// A ring of vertex indices, consecutive repeats (edges under a millimetre)
// dropped; empty if fewer than three corners are left.
json ring(const std::vector<glm::dvec3>& points, Vertices& vertices) {
  std::vector<std::int64_t> ids;
  for (const glm::dvec3& p : points) {
    const std::int64_t id = vertices.add(p);
    if (ids.empty() || ids.back() != id) ids.push_back(id);
  }
  while (ids.size() > 1 && ids.front() == ids.back()) ids.pop_back();
  if (ids.size() < 3) return json::array();
  return json(ids);
}

// A geometry of one Solid per shell (a MultiSolid if several): each shell a
// list of faces, each face one ring. `surface` gives each face's index into
// `surfaces` (the semantics), or none.
struct ShellFaces {
  std::vector<std::vector<glm::dvec3>> faces;
  std::vector<std::size_t> surface;
};

json solid_geometry(const std::vector<ShellFaces>& shells, const char* lod, const json& surfaces, Vertices& vertices) {
  json boundaries = json::array(), values = json::array();
  for (const ShellFaces& shell : shells) {
    json faces = json::array(), shell_values = json::array();
    for (std::size_t f = 0; f < shell.faces.size(); ++f) {
      json r = ring(shell.faces[f], vertices);
      if (r.empty()) continue;
      faces.push_back(json::array({std::move(r)}));
      shell_values.push_back(shell.surface[f]);
    }
    boundaries.push_back(json::array({std::move(faces)}));  // a solid: its outer shell
    values.push_back(json::array({std::move(shell_values)}));
  }
  const bool one = shells.size() == 1;
  json g;
  g["type"] = one ? "Solid" : "MultiSolid";
  g["lod"] = lod;
  g["boundaries"] = one ? boundaries[0] : boundaries;
  g["semantics"] = {{"surfaces", surfaces}, {"values", one ? values[0] : values}};
  return g;
}

// Faces of building b's shell s.
std::pair<std::size_t, std::size_t> shell_range(const GisBuilding& b, std::size_t s) {
  const std::size_t begin = b.shells.empty() ? 0 : b.shells[s];
  const std::size_t end = s + 1 < b.shells.size() ? b.shells[s + 1] : b.faces.size();
  return {begin, end};
}

json lod2(const GisBuilding& b, double ground, Vertices& vertices) {
  json surfaces = json::array();
  std::map<std::pair<std::string, std::string>, std::size_t> surface_of;  // (type, tag) -> index
  std::vector<ShellFaces> shells(std::max<std::size_t>(b.shells.size(), 1));
  for (std::size_t s = 0; s < shells.size(); ++s) {
    const auto [begin, end] = shell_range(b, s);
    for (std::size_t f = begin; f < end; ++f) {
      const std::string& tag = b.face_tags[f];
      const char* type = semantic_type(b.faces[f], tag, ground);
      const auto [it, added] = surface_of.try_emplace({type, tag}, surfaces.size());
      if (added) surfaces.push_back(tag.empty() ? json{{"type", type}} : json{{"type", type}, {"procex_tag", tag}});
      shells[s].faces.push_back(b.faces[f]);
      shells[s].surface.push_back(it->second);
    }
  }
  return solid_geometry(shells, "2.2", surfaces, vertices);
}

// The footprint (the shell's faces on the ground facing down) as a prism to
// the shell's top: the ground faces, the same reversed at the top, and a wall
// on every footprint edge no other ground face shares.
json lod1(const GisBuilding& b, double ground, Vertices& vertices) {
  const json surfaces = json::array({{{"type", "GroundSurface"}}, {{"type", "WallSurface"}}, {{"type", "RoofSurface"}}});
  std::vector<ShellFaces> shells;
  for (std::size_t s = 0; s < std::max<std::size_t>(b.shells.size(), 1); ++s) {
    const auto [begin, end] = shell_range(b, s);
    double top = -std::numeric_limits<double>::infinity();
    std::vector<const std::vector<glm::dvec3>*> base;
    for (std::size_t f = begin; f < end; ++f) {
      for (const glm::dvec3& p : b.faces[f]) top = std::max(top, p.z);
      if (on_ground(b.faces[f], ground) && newell_normal(b.faces[f]).z < 0) base.push_back(&b.faces[f]);
    }
    if (base.empty()) continue;
    std::map<std::pair<std::tuple<double, double>, std::tuple<double, double>>, int> edges;  // directed, plan only
    auto key = [](const glm::dvec3& p) { return std::make_tuple(p.x, p.y); };
    for (const auto* face : base)
      for (std::size_t i = 0; i < face->size(); ++i) ++edges[{key((*face)[i]), key((*face)[(i + 1) % face->size()])}];
    ShellFaces& shell = shells.emplace_back();
    for (const auto* face : base) {
      shell.faces.push_back(*face);
      shell.surface.push_back(0);
      std::vector<glm::dvec3> roof(face->rbegin(), face->rend());
      for (glm::dvec3& p : roof) p.z = top;
      shell.faces.push_back(std::move(roof));
      shell.surface.push_back(2);
      for (std::size_t i = 0; i < face->size(); ++i) {
        const glm::dvec3 a = (*face)[i], c = (*face)[(i + 1) % face->size()];
        if (edges.count({key(c), key(a)})) continue;  // inside the footprint: shared by two ground faces
        // The ground face runs clockwise seen from above (it faces down), so
        // a, c, then up is outward.
        shell.faces.push_back({a, {a.x, a.y, top}, {c.x, c.y, top}, c});
        shell.surface.push_back(1);
      }
    }
  }
  if (shells.empty()) return nullptr;
  return solid_geometry(shells, "1.2", surfaces, vertices);
}

}  // namespace

std::optional<std::string> cityjson_crs_problem(const std::string& crs) {
  if (auto problem = crs_problem(crs)) return problem;
  if (!crs_epsg_code(crs))
    return "CityJSON names its CRS by EPSG code (metadata.referenceSystem), and PROJ finds none for '" +
           crs.substr(0, 80) + (crs.size() > 80 ? "...'" : "'") +
           " (procex's local frame for longitude/latitude footprints has none): give --target-crs with an EPSG code "
           "in metres, e.g. the UTM zone (EPSG:326NN north, 327NN south)";
  return std::nullopt;
}

void write_cityjson(const std::filesystem::path& path, const std::string& crs, const std::vector<GisBuilding>& buildings) {
  if (const auto problem = cityjson_crs_problem(crs))
    throw IoError("cannot write '" + path.string() + "': " + *problem, path.string());
  glm::dvec3 low(std::numeric_limits<double>::infinity()), high(-std::numeric_limits<double>::infinity());
  for (const GisBuilding& b : buildings)
    for (const auto& face : b.faces)
      for (const glm::dvec3& p : face) low = glm::min(low, p), high = glm::max(high, p);
  if (buildings.empty() || !std::isfinite(low.x)) low = high = glm::dvec3(0.0);
  const glm::dvec3 translate = glm::floor(low);  // whole metres: the quantised integers stay small and positive

  Vertices vertices(translate);
  json objects = json::object();
  for (const GisBuilding& b : buildings) {
    double ground = std::numeric_limits<double>::infinity();
    for (const auto& face : b.faces)
      for (const glm::dvec3& p : face) ground = std::min(ground, p.z);
    json o;
    o["type"] = "Building";
    json attributes = json::object();
    for (const auto& [name, text] : b.properties) attributes[name] = json::parse(text, nullptr, false);
    if (!attributes.empty()) o["attributes"] = std::move(attributes);
    o["geometry"] = json::array();
    if (json g = lod1(b, ground, vertices); !g.is_null()) o["geometry"].push_back(std::move(g));
    if (!b.faces.empty()) o["geometry"].push_back(lod2(b, ground, vertices));
    objects[b.id] = std::move(o);
  }
  json doc;
  doc["type"] = "CityJSON";
  doc["version"] = "2.0";
  doc["transform"] = {{"scale", {kScale, kScale, kScale}}, {"translate", {translate.x, translate.y, translate.z}}};
  doc["metadata"] = {{"referenceSystem", "https://www.opengis.net/def/crs/EPSG/0/" + *crs_epsg_code(crs)},
                     {"geographicalExtent", {low.x, low.y, low.z, high.x, high.y, high.z}}};
  doc["CityObjects"] = std::move(objects);
  doc["vertices"] = vertices.take();
  write_file_atomically(path, doc.dump() + "\n");
}

}  // namespace procex
