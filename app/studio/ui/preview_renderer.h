// preview_renderer.h -- draws the 3D preview's image on a thread and OpenGL
// context of its own, so that drawing a new mesh does not hold up the
// window's frames: the window shows the last finished image meanwhile.
//
// Drawn in the window's frame, the city's preview (34,000 faces, 1,200 placed
// windows) held up that frame for its whole drawing on Mesa's software
// rasteriser, so the canvas's next frame waited for it (BENCHMARKS.md,
// Studio). llvmpipe runs the vertex stage and sorts triangles into tiles on
// the thread that issues the drawing, then hands the scene to its rasteriser
// threads (llvmpipe-N). Those are the screen's, shared by every context of the
// process (Mesa 22.3: one pair on two cores, whether one context exists or
// two), and they take scenes in the order they are handed over: a frame of
// the window handed over while a preview image is being filled waits for the
// rest of that image. What this thread takes from the window's frames is the
// issuing, the vertex stage and the binning, and the wait for the image to be
// filled; the frame that asks for an image goes on at once.
//
// Two images take turns: one is shown while the other is drawn. The one the
// window stops showing is given back with a fence after the window's
// commands that sampled it, and the renderer waits on that fence before it
// draws into it again.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include <glm/glm.hpp>

#include "app/studio/editor/preview_mesh.h"

struct GLFWwindow;
struct __GLsync;

namespace procex::studio {

// What one image shows.
struct PreviewShot {
  std::shared_ptr<const PreviewMesh> mesh;
  std::shared_ptr<const std::vector<float>> grid;  // ground grid lines (xyz pairs), in the mesh's frame
  glm::mat4 mvp{1.0f};
  int width = 16, height = 16;
  bool wireframe = false, anchors = true;
};

class PreviewRenderer {
 public:
  // Makes the renderer's context, sharing objects with `window`'s (on the
  // calling thread, which GLFW requires to be the main one); `finished` is
  // called from the renderer's thread when an image is ready to be taken.
  // Throws when the context cannot be made.
  PreviewRenderer(GLFWwindow* window, std::function<void()> finished);
  ~PreviewRenderer();
  PreviewRenderer(const PreviewRenderer&) = delete;
  PreviewRenderer& operator=(const PreviewRenderer&) = delete;

  // The image to draw next, in place of any asked for and not yet begun.
  void request(PreviewShot shot);
  // With the window's context current: the newest finished image becomes
  // the one shown (true when it changed).
  bool take_finished();
  // The image shown: its texture (0 before the first) and size.
  std::uint32_t texture() const { return shown_texture_; }
  int width() const { return shown_w_; }
  int height() const { return shown_h_; }
  // Whether an image asked for is not yet shown (being drawn, or finished and not taken).
  bool busy() const;
  // CPU time the renderer's thread has used, uploading meshes and issuing the drawing.
  double cpu_ms() const;
  // Whether an image is being drawn, and how many have been finished: two readings tell whether
  // the renderer drew between them (the frame report: the rasteriser's threads are shared, so a
  // frame of the window's during which an image was drawn counts that image's filling too).
  struct Progress {
    bool drawing = false;
    std::uint64_t finished = 0;
  };
  Progress progress() const;

 private:
  struct Image {
    std::uint32_t fbo = 0, texture = 0, depth = 0;
    int width = 0, height = 0;
    __GLsync* released = nullptr;  // the window's commands that sampled it are done when this signals
  };
  struct Scene;
  void run();
  void draw(const PreviewShot& shot, Image& image);

  GLFWwindow* context_ = nullptr;  // a hidden window, for its context
  std::function<void()> finished_callback_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<PreviewShot> pending_;
  bool drawing_ = false, stop_ = false;
  Image images_[2];
  int shown_ = -1, finished_ = -1;  // indices into images_
  std::uint64_t images_finished_ = 0;
  double cpu_ms_ = 0;
  // The image shown, for the window's thread only (written by take_finished).
  std::uint32_t shown_texture_ = 0;
  int shown_w_ = 0, shown_h_ = 0;
  std::unique_ptr<Scene> scene_;  // the renderer thread's GL objects
  std::thread thread_;
};

}  // namespace procex::studio
