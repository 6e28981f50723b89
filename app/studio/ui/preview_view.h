// preview_view.h -- the 3D preview panel: renders the evaluated meshes into an
// offscreen framebuffer (shaded by face tag, the meshes placed on them drawn
// instanced, anchor markers and wireframe on request, ground grid)
// and shows it as an ImGui image; mouse drags orbit (left), pan (middle or
// shift+left), the wheel zooms. Everything is drawn relative to the mesh's
// origin (PreviewMesh::origin), the camera too, so float32 keeps its
// precision at UTM coordinates.
#pragma once

#include <cstdint>
#include <memory>

#include "app/studio/editor/orbit_camera.h"
#include "app/studio/editor/preview_mesh.h"

namespace procex::studio {

class PreviewView {
 public:
  PreviewView();
  ~PreviewView();
  PreviewView(const PreviewView&) = delete;
  PreviewView& operator=(const PreviewView&) = delete;

  // Uploads a new mesh when it differs from the one shown. The first mesh is framed.
  void set_mesh(std::shared_ptr<const PreviewMesh> mesh);
  // Draws into the current ImGui window, filling its content region.
  void draw();
  void frame_all();
  // The next mesh set is framed as the first one was (another scene: a viewed file).
  void frame_next_mesh() { framed_ = false; }
  // Turns the camera to yaw and pitch (degrees), keeping its target and distance.
  void look_from(float yaw_deg, float pitch_deg);

  // The offscreen image's texture, and how many times it has been redrawn
  // (a new count: the pixels showing it are stale).
  std::uintptr_t texture() const;
  std::uint64_t renders() const { return renders_; }
  // The UI thread's CPU time spent so far uploading meshes and issuing the
  // image's drawing (the rasteriser's threads fill it later): the frame report's split.
  double upload_cpu_ms() const { return upload_cpu_ms_; }
  double render_cpu_ms() const { return render_cpu_ms_; }

  bool wireframe = false;
  bool anchors = true;  // markers at the resolved anchors
  // Screen rectangle of the last rendered image (for screenshot checks).
  float image_x = 0, image_y = 0, image_w = 0, image_h = 0;

 private:
  struct Gl;
  void render(int width, int height);
  std::unique_ptr<Gl> gl_;
  std::shared_ptr<const PreviewMesh> mesh_;
  OrbitCamera camera_;  // in the shown mesh's frame: from origin_
  glm::dvec3 origin_{0.0};  // the last non-empty mesh's PreviewMesh::origin
  bool framed_ = false;
  // The offscreen image is redrawn only when something it shows changed
  // (software GL under Xvfb makes every redraw count).
  bool stale_ = true;
  bool drawn_wireframe_ = false, drawn_anchors_ = true;
  std::uint64_t renders_ = 0;
  double upload_cpu_ms_ = 0, render_cpu_ms_ = 0;
};

}  // namespace procex::studio
