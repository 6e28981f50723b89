// glb_loader.h -- reads a .glb for the preview on a thread of its own, so the
// window keeps drawing, and says how far the read has got, while a large file
// loads. A newer load replaces one still running (whose result is dropped);
// a file the reader refuses comes back as its message, never as a crash.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "app/studio/editor/preview_mesh.h"

namespace procex::studio {

class GlbLoader {
 public:
  GlbLoader();
  ~GlbLoader();  // waits for the load under way
  GlbLoader(const GlbLoader&) = delete;
  GlbLoader& operator=(const GlbLoader&) = delete;

  // Starts reading `file` (replacing any load not yet taken).
  void load(std::filesystem::path file);

  struct Progress {
    std::filesystem::path file;
    std::size_t size = 0;    // bytes
    bool preparing = false;  // read; the preview is being made
  };
  // The load under way, if any.
  std::optional<Progress> progress() const;

  struct Loaded {
    std::filesystem::path file;
    std::shared_ptr<const PreviewMesh> mesh;  // null when it failed
    std::string error;                        // why, naming the file
  };
  // The finished load, handed over once; nothing while loading or idle.
  std::optional<Loaded> take();

 private:
  void run();

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<std::filesystem::path> pending_;
  std::optional<Progress> progress_;
  std::optional<Loaded> done_;
  bool stop_ = false;
  std::thread thread_;  // last: starts after every other member exists
};

}  // namespace procex::studio
