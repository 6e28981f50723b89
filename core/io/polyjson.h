// Reading the synthetic benchmark format of data/synthetic/ (see its
// README): a shape {"loops": [[[x, y], ...], ...], "weights": [[w, ...], ...]}
// or a collection {"polygons": [shape, ...]}. Loops are implicitly closed.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "core/geom/footprint.h"

namespace procex {

struct PolyShape {
  std::vector<std::vector<glm::dvec2>> loops;
  // CGAL-convention weights, weights[i][j] for the edge from loops[i][j] to
  // loops[i][j + 1 mod n]; empty when the file gives none.
  std::vector<std::vector<double>> weights;
};

// A shape file gives one shape, a collection file all of its shapes. Throws
// IoError naming the file and the JSON pointer of the first bad value.
std::vector<PolyShape> read_polyjson_file(const std::filesystem::path& path);
std::vector<PolyShape> parse_polyjson(std::string_view text, const std::string& source = "<memory>");

// A CGAL weight w moves its edge t / w at time t, so its face rises at atan(w)
// from the horizontal: angle from the vertical = 90 - atan(w) degrees.
// Requires w > 0 (throws InputError otherwise).
double weight_to_angle_deg(double weight);

// The weights the README's weighted reference runs used when a file has none:
// 1.0, 0.5, 2.0, 1.0, ... along every loop, starting at edge 0.
std::vector<std::vector<double>> reference_cycle_weights(const PolyShape& shape);

// The shape as a footprint, edge ids numbered across loops: with weights,
// each edge at weight_to_angle_deg(w); without, every edge at default_angle_deg.
Footprint to_footprint(const PolyShape& shape, double default_angle_deg = 45.0);
// The shape as a footprint with explicit weights (same layout as PolyShape::weights).
Footprint to_footprint(const PolyShape& shape, const std::vector<std::vector<double>>& weights);

}  // namespace procex
