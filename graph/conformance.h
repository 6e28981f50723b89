// conformance.h -- generic checks every node type must pass (Gaffer-style):
// each parameter moves the output hash, defaults evaluate without crashing,
// and a .pxg round trip keeps the hash and the bytes.
//
// Used by tests/graph for its test nodes and by tests/nodes for every
// registered node:  for (auto& t : NodeRegistry::global().all())
//                     EXPECT_EQ(check_node_type(*t, samples), std::vector<std::string>{});
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "graph/registry.h"
#include "graph/value.h"

namespace procex {

// A sample value for every input type the node types under test use
// (built-in number, vector and string types have defaults).
using SampleInputs = std::map<const ValueType*, Value>;

// Problems found, one sentence each; empty when the type conforms. Relative
// file paths in parameters resolve against `folder` (EvalOptions::folder).
std::vector<std::string> check_node_type(const NodeType& type, const SampleInputs& samples,
                                         const std::filesystem::path& folder = {});

// The .cc files under `dir` (recursively) that use PROCEX_REGISTER_NODE but
// registered nothing in NodeRegistry::global(): node files the linker dropped
// or that are missing from the build. Empty when every node file is registered.
std::vector<std::filesystem::path> unregistered_node_files(const std::filesystem::path& dir);

// Whether `type` was registered by a .cc file directly in `dir`. Registered
// source files are compared by folder and file name only: __FILE__ is relative
// to the compiler's working folder when ccache rewrites paths (CCACHE_BASEDIR).
bool registered_in(const NodeType& type, const std::filesystem::path& dir);

// Problems with a recipe file's round trip: it must load, save to exactly the
// bytes it was read from, and keep every output hash. Empty when it conforms.
// (For "every sample file round-trips byte-identically".)
std::vector<std::string> check_pxg_round_trip(const std::filesystem::path& file);

// A different valid value for the parameter (next enum choice, flipped bool,
// a number moved within its range, ...), or an empty Value when none exists.
Value vary_param(const ParamDecl& p);

}  // namespace procex
