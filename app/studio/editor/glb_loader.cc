#include "app/studio/editor/glb_loader.h"

#include <utility>

#include "core/io/glb_read.h"
#include "core/io/gltf_write.h"

namespace procex::studio {

GlbLoader::GlbLoader() : thread_([this] { run(); }) {}

GlbLoader::~GlbLoader() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void GlbLoader::load(std::filesystem::path file) {
  {
    std::lock_guard lock(mutex_);
    pending_ = std::move(file);
    done_.reset();
  }
  wake_.notify_all();
}

std::optional<GlbLoader::Progress> GlbLoader::progress() const {
  std::lock_guard lock(mutex_);
  if (pending_) return Progress{*pending_, 0, false};
  return progress_;
}

std::optional<GlbLoader::Loaded> GlbLoader::take() {
  std::lock_guard lock(mutex_);
  return std::exchange(done_, std::nullopt);
}

void GlbLoader::run() {
  std::unique_lock lock(mutex_);
  for (;;) {
    wake_.wait(lock, [this] { return stop_ || pending_; });
    if (stop_) return;
    const std::filesystem::path file = std::move(*pending_);
    pending_.reset();
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(file, ec);
    progress_ = Progress{file, ec ? 0 : static_cast<std::size_t>(size), false};
    lock.unlock();
    Loaded out{file, nullptr, {}};
    try {
      const GltfScene scene = read_glb_scene(file);
      {
        std::lock_guard l(mutex_);
        progress_->preparing = true;
      }
      out.mesh = std::make_shared<const PreviewMesh>(make_preview(scene));
    } catch (const std::exception& e) {
      out.error = e.what();
    }
    lock.lock();
    progress_.reset();
    if (!pending_) done_ = std::move(out);  // else a newer load replaces it
  }
}

}  // namespace procex::studio
