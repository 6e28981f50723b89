#include "core/io/polyjson.h"

#include <cmath>
#include <numbers>

#include "core/geom/error.h"
#include "core/io/io_error.h"
#include "core/io/json_read.h"

namespace procex {

using nlohmann::json;
using io_detail::array_at;
using io_detail::ValueProblem;

namespace {

PolyShape read_shape(const json& shape, const std::string& pointer) {
  if (!shape.is_object()) throw ValueProblem{pointer, "a shape must be an object with \"loops\""};
  const auto loops = shape.find("loops");
  if (loops == shape.end()) throw ValueProblem{pointer + "/loops", "the shape has no loops"};
  const std::string lpointer = pointer + "/loops";
  array_at(*loops, lpointer);
  PolyShape out;
  out.loops.resize(loops->size());
  for (std::size_t i = 0; i < loops->size(); ++i) {
    const std::string ipointer = lpointer + "/" + std::to_string(i);
    const json& loop = array_at((*loops)[i], ipointer);
    out.loops[i].reserve(loop.size());
    for (std::size_t j = 0; j < loop.size(); ++j) out.loops[i].push_back(io_detail::point_in(loop, ipointer, j));
  }
  const auto weights = shape.find("weights");
  if (weights == shape.end() || weights->is_null()) return out;
  const std::string wpointer = pointer + "/weights";
  array_at(*weights, wpointer);
  if (weights->size() != out.loops.size())
    throw ValueProblem{wpointer, "expected one weight list per loop (" + std::to_string(out.loops.size()) + "), found " +
                                     std::to_string(weights->size())};
  out.weights.resize(out.loops.size());
  for (std::size_t i = 0; i < weights->size(); ++i) {
    const std::string ipointer = wpointer + "/" + std::to_string(i);
    const json& list = array_at((*weights)[i], ipointer);
    if (list.size() != out.loops[i].size())
      throw ValueProblem{ipointer, "loop " + std::to_string(i) + " has " + std::to_string(out.loops[i].size()) +
                                       " edges but " + std::to_string(list.size()) + " weights"};
    for (std::size_t j = 0; j < list.size(); ++j) {
      const double w = io_detail::number_in(list, ipointer, j);
      if (w <= 0.0) throw ValueProblem{ipointer + "/" + std::to_string(j), "a weight must be positive"};
      out.weights[i].push_back(w);
    }
  }
  return out;
}

}  // namespace

std::vector<PolyShape> parse_polyjson(std::string_view text, const std::string& source) {
  const json doc = io_detail::parse_json(text, source);
  try {
    if (!doc.is_object()) throw ValueProblem{"", "the document must be a shape or a {\"polygons\": [...]} collection"};
    std::vector<PolyShape> shapes;
    if (const auto polygons = doc.find("polygons"); polygons != doc.end()) {
      array_at(*polygons, "/polygons");
      shapes.reserve(polygons->size());
      for (std::size_t i = 0; i < polygons->size(); ++i)
        shapes.push_back(read_shape((*polygons)[i], "/polygons/" + std::to_string(i)));
    } else {
      shapes.push_back(read_shape(doc, ""));
    }
    return shapes;
  } catch (const ValueProblem& problem) {
    throw IoError(source + ": at '" + problem.pointer + "': " + problem.message, source, problem.pointer);
  }
}

std::vector<PolyShape> read_polyjson_file(const std::filesystem::path& path) {
  return parse_polyjson(io_detail::read_text_file(path), path.string());
}

double weight_to_angle_deg(double weight) {
  if (!(weight > 0.0) || !std::isfinite(weight))
    throw InputError("weight " + std::to_string(weight) + " is not a positive finite number");
  return 90.0 - std::atan(weight) * 180.0 / std::numbers::pi;
}

std::vector<std::vector<double>> reference_cycle_weights(const PolyShape& shape) {
  static constexpr double kCycle[] = {1.0, 0.5, 2.0};
  std::vector<std::vector<double>> weights(shape.loops.size());
  for (std::size_t i = 0; i < shape.loops.size(); ++i)
    for (std::size_t j = 0; j < shape.loops[i].size(); ++j) weights[i].push_back(kCycle[j % 3]);
  return weights;
}

Footprint to_footprint(const PolyShape& shape, double default_angle_deg) {
  if (!shape.weights.empty()) return to_footprint(shape, shape.weights);
  return make_footprint(shape.loops, default_angle_deg);
}

Footprint to_footprint(const PolyShape& shape, const std::vector<std::vector<double>>& weights) {
  if (weights.size() != shape.loops.size())
    throw InputError("expected one weight list per loop (" + std::to_string(shape.loops.size()) + "), got " +
                     std::to_string(weights.size()));
  Footprint fp = make_footprint(shape.loops, 45.0);
  for (std::size_t i = 0; i < fp.loops.size(); ++i) {
    if (weights[i].size() != fp.loops[i].edges.size())
      throw InputError("loop " + std::to_string(i) + " has " + std::to_string(fp.loops[i].edges.size()) +
                           " edges but " + std::to_string(weights[i].size()) + " weights",
                       static_cast<int>(i));
    for (std::size_t j = 0; j < weights[i].size(); ++j) {
      try {
        fp.loops[i].edges[j].angle_deg = weight_to_angle_deg(weights[i][j]);
      } catch (const InputError& e) {
        throw InputError(std::string(e.what()) + " (loop " + std::to_string(i) + ", edge " + std::to_string(j) + ")",
                         static_cast<int>(i), static_cast<int>(j));
      }
    }
  }
  return fp;
}

}  // namespace procex
