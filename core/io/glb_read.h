// Reading back a .glb procex wrote (a batch shard, an export) without a glTF
// document of it: one streamed pass over the JSON chunk notes where each
// element of its arrays lies (8 bytes per element), then a building's node,
// mesh and accessors are parsed from those ranges, and its arrays read from
// the binary chunk by their buffer views' ranges, only when it is asked for.
// So memory holds the index and one building, not the file: procex merge
// reads parts of any size this way (BENCHMARKS "What procex merge holds of a
// part").
// Every index, offset, length and count in the file is its maker's: each is
// checked before it is used, and a file that is not as write_glb writes it
// is refused with an IoError naming it and what is wrong. External buffer
// and image URIs are refused: a .glb from procex holds everything in itself.
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/io/gltf_write.h"

namespace procex {

class GlbReader {
 public:
  // Checks the file's header, indexes its JSON, and reads its placed meshes
  // (with their images) and its scene's extras; its buildings are read when
  // asked for. Throws IoError naming the file.
  explicit GlbReader(const std::filesystem::path& path);
  // The same over a file's bytes already in memory, which must outlive the
  // reader; path names them in messages.
  GlbReader(std::string_view bytes, const std::filesystem::path& path);
  GlbReader(const GlbReader&) = delete;
  GlbReader& operator=(const GlbReader&) = delete;
  ~GlbReader();
  // The length the file's header gives, checked as the constructor checks it
  // (against the file's size and its chunks' lengths) without reading on:
  // what the file claims to hold. Throws IoError naming the file.
  static std::uint64_t length(const std::filesystem::path& path);

  // The scene's extras, each value as compact JSON text.
  const std::map<std::string, std::string>& extras() const;
  // The placed meshes; the buildings' instances index these.
  const std::vector<GltfMeshData>& prototypes() const;
  // How many buildings the file holds: its scene's nodes.
  std::size_t buildings() const;
  // Building i (in file order), read from the file now. Throws IoError as
  // the constructor does.
  GltfMeshData building(std::size_t i) const;
  // What the buildings take of the file, at least: their nodes' and meshes'
  // JSON and the binary buffer less all the placed meshes' and images' bytes
  // could take. A .glb they are merged into holds all of it whatever else it
  // holds (the file's head, placed meshes and images are what parts share).
  std::uint64_t building_bytes() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// A whole file read back: what write_glb wrote, so writing it again gives
// the same bytes. Throws IoError as GlbReader does; read_glb also if the file
// holds placed-mesh instances (they need read_glb_scene's prototypes).
std::vector<GltfMeshData> read_glb(const std::filesystem::path& path);
GltfScene read_glb_scene(const std::filesystem::path& path);
// The same on a file's bytes already in memory; path names it in messages.
GltfScene parse_glb_scene(std::string_view bytes, const std::filesystem::path& path);

}  // namespace procex
