#include "experiments/shapes/shape_catalog.h"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace lpd::experiments {
namespace {

using energy::Point3;
using Profile = std::vector<std::pair<double, double>>;

double Parameter(const ShapeSpec& spec, const std::string& key) {
  const auto& defaults = ShapeParameterDefaults().at(spec.name);
  const auto found = spec.parameters.find(key);
  const double value = found == spec.parameters.end() ? defaults.at(key) : found->second;
  if (!std::isfinite(value) || value <= 0.0) {
    throw std::invalid_argument("shape " + spec.name + ": parameter " + key +
                                " must be a positive number");
  }
  return value;
}

std::string Describe(const ShapeSpec& spec) {
  std::ostringstream text;
  text << spec.name << "(";
  bool first = true;
  for (const auto& [key, unused] : ShapeParameterDefaults().at(spec.name)) {
    text << (first ? "" : ", ") << key << "=" << Parameter(spec, key);
    first = false;
  }
  text << ")";
  return text.str();
}

ProceduralShape MakeBox(const std::string& description, const Point3& size) {
  const Point3 h = 0.5 * size;
  std::vector<std::unique_ptr<SurfacePatch>> faces;
  std::vector<FeatureSegment> edges;
  for (int axis = 0; axis < 3; ++axis) {
    const int b = (axis + 1) % 3, c = (axis + 2) % 3;
    for (double side : {-1.0, 1.0}) {
      std::vector<Point3> corners;
      for (const auto& [sb, sc] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
        Point3 corner;
        corner[axis] = side * h[axis];
        corner[b] = sb * h[b];
        corner[c] = sc * h[c];
        corners.push_back(corner);
      }
      Point3 outward = Point3::Zero();
      outward[axis] = side;
      faces.push_back(std::make_unique<ConvexPolygon>(corners, outward));
      // The four edges parallel to axis b sit at (axis = +-h, c = +-h); collect each once.
      for (double sc : {-1.0, 1.0}) {
        Point3 a = Point3::Zero(), z = Point3::Zero();
        a[axis] = z[axis] = side * h[axis];
        a[c] = z[c] = sc * h[c];
        a[b] = -h[b];
        z[b] = h[b];
        edges.push_back({a, z});
      }
    }
  }
  return ProceduralShape(description, std::move(faces), std::move(edges), {});
}

}  // namespace

const std::map<std::string, std::map<std::string, double>>& ShapeParameterDefaults() {
  static const std::map<std::string, std::map<std::string, double>> defaults = {
      {"box", {{"size_x", 1.0}, {"size_y", 0.8}, {"size_z", 0.6}}},
      {"cube", {{"size", 1.0}}},
      {"sphere", {{"radius", 0.5}}},
      {"cylinder", {{"radius", 0.5}, {"height", 1.0}}},
      {"cone", {{"apex_angle", 60.0}, {"radius", 0.5}}},
      {"cad_part", {{"sweep", 270.0}}},
      {"sheets", {{"size", 1.0}, {"gap", 0.02}}},
  };
  return defaults;
}

ProceduralShape MakeSolidOfRevolution(const std::string& description, const Profile& profile,
                                      double sweep_degrees) {
  if (profile.size() < 3 || profile.front().first != 0.0 || profile.back().first != 0.0) {
    throw std::invalid_argument(description +
                                ": a profile needs 3+ vertices and must start and end on the axis");
  }
  if (!(sweep_degrees > 0.0 && sweep_degrees <= 360.0)) {
    throw std::invalid_argument(description + ": sweep must be in (0, 360] degrees");
  }
  const double sweep = sweep_degrees * M_PI / 180.0;
  const bool closed_by_cuts = sweep_degrees < 360.0;
  const RevolutionFrame frame;
  std::vector<std::unique_ptr<SurfacePatch>> patches;
  std::vector<FeatureSegment> segments;
  std::vector<FeatureArc> arcs;
  const size_t last = profile.size() - 1;
  for (size_t v = 0; v < last; ++v) {
    const auto [r0, z0] = profile[v];
    const auto [r1, z1] = profile[v + 1];
    if (r0 < 0.0 || r1 < 0.0) throw std::invalid_argument(description + ": profile r < 0");
    if (closed_by_cuts && z1 < z0) {
      throw std::invalid_argument(description + ": a cut solid needs a profile with rising z");
    }
    if (r0 == 0.0 && r1 == 0.0) continue;  // runs along the axis: no area
    patches.push_back(std::make_unique<RevolvedSegment>(frame, r0, z0, r1, z1, 0.0, sweep));
    if (closed_by_cuts) {
      for (double angle : {0.0, sweep}) {
        segments.push_back({frame.At(r0, z0, angle), frame.At(r1, z1, angle)});
        if (z1 == z0) continue;  // a flat profile step bounds no cut area
        std::vector<Point3> corners = {frame.At(0.0, z0, angle), frame.At(r0, z0, angle),
                                       frame.At(r1, z1, angle), frame.At(0.0, z1, angle)};
        if (r0 == 0.0) corners.erase(corners.begin());
        if (r1 == 0.0) corners.pop_back();
        // The solid lies at angles inside (0, sweep): each cut faces away from it.
        const Point3 tangent = frame.At(1.0, 0.0, angle + 0.5 * M_PI) - frame.origin;
        patches.push_back(
            std::make_unique<ConvexPolygon>(corners, angle == 0.0 ? -tangent : tangent));
      }
    }
  }
  for (size_t v = 1; v < last; ++v) {  // every corner off the axis is a sharp circular edge
    const auto [r, z] = profile[v];
    const double cross = (r - profile[v - 1].first) * (profile[v + 1].second - z) -
                         (z - profile[v - 1].second) * (profile[v + 1].first - r);
    if (r > 0.0 && cross != 0.0) {
      arcs.push_back({frame.At(0.0, z, 0.0), frame.axis, frame.reference, r, 0.0, sweep});
    }
  }
  for (size_t end : {size_t{0}, last}) {  // a cone apex on the axis is a feature point
    const size_t next = end == 0 ? 1 : last - 1;
    if (profile[next].second != profile[end].second) {
      const Point3 apex = frame.At(0.0, profile[end].second, 0.0);
      segments.push_back({apex, apex});
    }
  }
  if (closed_by_cuts && std::abs(sweep_degrees - 180.0) > 1e-9) {  // the cuts meet on the axis
    segments.push_back({frame.At(0.0, profile.front().second, 0.0),
                        frame.At(0.0, profile.back().second, 0.0)});
  }
  return ProceduralShape(description, std::move(patches), std::move(segments), std::move(arcs));
}

ShapeSpec ParseShapeSpec(const std::string& text) {
  ShapeSpec spec;
  const size_t colon = text.find(':');
  spec.name = text.substr(0, colon);
  if (spec.name.empty()) throw std::invalid_argument("empty shape name in '" + text + "'");
  if (colon == std::string::npos) return spec;
  std::istringstream items(text.substr(colon + 1));
  std::string item;
  while (std::getline(items, item, ',')) {
    const size_t equals = item.find('=');
    char* end = nullptr;
    const double value =
        equals == std::string::npos ? NAN : std::strtod(item.c_str() + equals + 1, &end);
    if (equals == std::string::npos || equals == 0 || end == item.c_str() + equals + 1 ||
        *end != '\0') {
      throw std::invalid_argument("malformed shape parameter '" + item + "' in '" + text +
                                  "' (expected key=number)");
    }
    spec.parameters[item.substr(0, equals)] = value;
  }
  return spec;
}

ProceduralShape MakeShape(const ShapeSpec& spec) {
  const auto found = ShapeParameterDefaults().find(spec.name);
  if (found == ShapeParameterDefaults().end()) {
    std::string names;
    for (const auto& [name, unused] : ShapeParameterDefaults()) names += " " + name;
    throw std::invalid_argument("unknown shape '" + spec.name + "' (known:" + names + ")");
  }
  for (const auto& [key, unused] : spec.parameters) {
    if (!found->second.count(key)) {
      throw std::invalid_argument("shape " + spec.name + " has no parameter '" + key + "'");
    }
  }
  const std::string description = Describe(spec);
  const auto p = [&spec](const std::string& key) { return Parameter(spec, key); };
  if (spec.name == "box") return MakeBox(description, Point3(p("size_x"), p("size_y"), p("size_z")));
  if (spec.name == "cube") return MakeBox(description, Point3::Constant(p("size")));
  if (spec.name == "sphere") {
    std::vector<std::unique_ptr<SurfacePatch>> patches;
    patches.push_back(std::make_unique<Sphere>(Point3::Zero(), p("radius")));
    return ProceduralShape(description, std::move(patches), {}, {});
  }
  if (spec.name == "cylinder") {
    const double r = p("radius"), h = 0.5 * p("height");
    return MakeSolidOfRevolution(description, {{0, -h}, {r, -h}, {r, h}, {0, h}}, 360.0);
  }
  if (spec.name == "cone") {
    const double angle = p("apex_angle");
    if (angle >= 180.0) throw std::invalid_argument("cone: apex_angle must be below 180 degrees");
    const double r = p("radius");
    const double height = r / std::tan(0.5 * angle * M_PI / 180.0);
    return MakeSolidOfRevolution(description, {{0, 0}, {r, 0}, {0, height}}, 360.0);
  }
  if (spec.name == "sheets") {
    const double h = 0.5 * p("size"), z = 0.5 * p("gap");
    std::vector<std::unique_ptr<SurfacePatch>> sheets;
    for (double side : {-1.0, 1.0}) {
      sheets.push_back(std::make_unique<ConvexPolygon>(
          std::vector<Point3>{{-h, -h, side * z}, {h, -h, side * z}, {h, h, side * z},
                              {-h, h, side * z}},
          Point3(0.0, 0.0, side)));
    }
    return ProceduralShape(description, std::move(sheets), {}, {});
  }
  // cad_part: a base cylinder, a 45-degree chamfer, a waist cylinder, a flat shoulder (concave
  // edge at its inner rim), a neck cylinder and a conical tip cut flat.
  return MakeSolidOfRevolution(description,
                               {{0.0, 0.0}, {0.5, 0.0}, {0.5, 0.3}, {0.35, 0.45}, {0.35, 0.7},
                                {0.2, 0.7}, {0.2, 0.9}, {0.1, 1.0}, {0.0, 1.0}},
                               p("sweep"));
}

}  // namespace lpd::experiments
