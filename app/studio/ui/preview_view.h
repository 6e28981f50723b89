// preview_view.h -- the 3D preview panel: the evaluated meshes drawn into an
// image (shaded by face tag, the meshes placed on them drawn instanced,
// anchor markers and wireframe on request, ground grid) on a thread and
// OpenGL context of their own (ui/preview_renderer.h), shown as an ImGui
// image once finished; mouse drags orbit (left), pan (middle or shift+left),
// the wheel zooms. Everything is drawn relative to the mesh's origin
// (PreviewMesh::origin), the camera too, so float32 keeps its precision at
// UTM coordinates.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "app/studio/editor/orbit_camera.h"
#include "app/studio/editor/preview_mesh.h"

struct GLFWwindow;

namespace procex::studio {

class PreviewRenderer;

class PreviewView {
 public:
  // `window`: the studio's, whose context shows the images (see PreviewRenderer).
  explicit PreviewView(GLFWwindow* window);
  ~PreviewView();
  PreviewView(const PreviewView&) = delete;
  PreviewView& operator=(const PreviewView&) = delete;

  // The mesh to show, when it differs from the one shown. The first mesh is framed.
  void set_mesh(std::shared_ptr<const PreviewMesh> mesh);
  // Draws into the current ImGui window, filling its content region.
  void draw();
  void frame_all();
  // The next mesh set is framed as the first one was (another scene: a viewed file).
  void frame_next_mesh() { framed_ = false; }
  // Turns the camera to yaw and pitch (degrees), keeping its target and distance.
  void look_from(float yaw_deg, float pitch_deg);

  // The image shown (its texture and size), and how many finished images have
  // been shown (a new count: the pixels showing it are stale).
  std::uintptr_t texture() const;
  int texture_width() const;
  int texture_height() const;
  std::uint64_t renders() const { return renders_; }
  // Whether the image shown is of the mesh, camera and size as they are now.
  bool current() const;
  // The CPU time the preview's thread has used so far (uploading meshes and
  // issuing the drawing; the rasteriser's threads fill the image): the frame report's split.
  double render_cpu_ms() const;
  // Whether its thread is drawing an image, and how many it has finished (PreviewRenderer::progress).
  bool drawing() const;
  std::uint64_t images_finished() const;

  bool wireframe = false;
  bool anchors = true;  // markers at the resolved anchors
  // Screen rectangle of the last rendered image (for screenshot checks).
  float image_x = 0, image_y = 0, image_w = 0, image_h = 0;

 private:
  // Asks for an image when what it shows changed.
  void request(int width, int height);
  std::unique_ptr<PreviewRenderer> renderer_;
  std::shared_ptr<const PreviewMesh> mesh_;
  std::shared_ptr<const std::vector<float>> grid_;  // ground grid lines, in the frame of origin_
  OrbitCamera camera_;  // in the shown mesh's frame: from origin_
  glm::dvec3 origin_{0.0};  // the last non-empty mesh's PreviewMesh::origin
  bool framed_ = false;
  // An image is asked for only when something it shows changed
  // (software GL under Xvfb makes every redraw count).
  bool stale_ = true;
  bool drawn_wireframe_ = false, drawn_anchors_ = true;
  int drawn_w_ = 0, drawn_h_ = 0;
  std::uint64_t renders_ = 0;
};

}  // namespace procex::studio
