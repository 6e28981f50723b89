// Errors raised by core/ on bad user input or when an algorithm cannot finish.
// Each names where the problem is, so the caller can show it next to the data.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace procex {

// The footprint itself is unusable (fewer than 3 distinct vertices, NaN, a
// self-intersecting loop, ...). loop/vertex are -1 when they do not apply.
class InputError : public std::runtime_error {
 public:
  InputError(const std::string& what, int loop = -1, int vertex = -1)
      : std::runtime_error(what), loop_(loop), vertex_(vertex) {}
  int loop() const { return loop_; }
  int vertex() const { return vertex_; }

 private:
  int loop_;
  int vertex_;
};

// The sweep could not resolve an event. Names the height and the edge ids involved.
class SweepError : public std::runtime_error {
 public:
  SweepError(const std::string& what, double height, std::vector<int> edge_ids)
      : std::runtime_error(what), height_(height), edge_ids_(std::move(edge_ids)) {}
  double height() const { return height_; }
  const std::vector<int>& edge_ids() const { return edge_ids_; }

 private:
  double height_;
  std::vector<int> edge_ids_;
};

// The sweep passed one of its limits (SweepBudget): the input makes the
// engine run away. Not retried at other tolerances.
class SweepBudgetError : public SweepError {
 public:
  using SweepError::SweepError;
};

// The roof does not close because the recipe says so: with no events left,
// some edges rise forever (vertical or leaning out) and no maximum height caps
// them. A refusal of the input, not a failure of the engine.
class SweepOpenError : public SweepError {
 public:
  using SweepError::SweepError;
};

// Assembling or checking a mesh failed (a face OpenMesh refused, ...).
class MeshError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace procex
