// test_nodes.h -- small node types for graph/ tests (and the .pxg fuzzer):
// arithmetic on floats, a failing node, a pass-through switch, a slow node
// that polls cancellation, a sum with a variadic number of inputs, a two-way pick, and one node
// with a parameter of every built-in type.
#pragma once

#include <atomic>
#include <string>

namespace procex::test {

// How many times each test node type's evaluate ran (all types together and per type).
std::atomic<int>& evaluations();
int evaluations_of(const std::string& type);
void reset_evaluations();
// How many times test.FileSize's hash_extra ran (it runs when the node is planned).
std::atomic<int>& file_size_hashes();

}  // namespace procex::test
