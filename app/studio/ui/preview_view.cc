#include "app/studio/ui/preview_view.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "app/studio/ui/preview_renderer.h"

namespace procex::studio {

// A finished image wakes the window's event loop, which then shows it.
PreviewView::PreviewView(GLFWwindow* window) : renderer_(std::make_unique<PreviewRenderer>(window, [] { glfwPostEmptyEvent(); })) {}
PreviewView::~PreviewView() = default;

std::uintptr_t PreviewView::texture() const { return renderer_->texture(); }
int PreviewView::texture_width() const { return renderer_->width(); }
int PreviewView::texture_height() const { return renderer_->height(); }
double PreviewView::render_cpu_ms() const { return renderer_->cpu_ms(); }
bool PreviewView::drawing() const { return renderer_->progress().drawing; }
std::uint64_t PreviewView::images_finished() const { return renderer_->progress().finished; }

bool PreviewView::current() const {
  return !stale_ && wireframe == drawn_wireframe_ && anchors == drawn_anchors_ && !renderer_->busy();
}

void PreviewView::look_from(float yaw_deg, float pitch_deg) {
  camera_.yaw = yaw_deg;
  camera_.pitch = pitch_deg;
  stale_ = true;
}

void PreviewView::set_mesh(std::shared_ptr<const PreviewMesh> mesh) {
  if (mesh == mesh_) return;
  mesh_ = std::move(mesh);
  stale_ = true;
  if (mesh_ && !mesh_->empty()) {
    // The camera keeps looking at the same place as the mesh's origin moves
    // (an edit that grows the building moves its bounds' centre).
    camera_.target += glm::vec3(origin_ - mesh_->origin);
    origin_ = mesh_->origin;
    // A ground grid around the mesh, at its lowest height, in 1-2-5 steps,
    // its lines on multiples of the step in the scene's coordinates.
    const glm::dvec3 lo = mesh_->min, hi = mesh_->max;
    const double extent = std::max(hi.x - lo.x, hi.y - lo.y) * 1.5 + 1.0;
    const double step = std::pow(10.0, std::floor(std::log10(extent / 10.0)));
    const glm::dvec2 c((lo.x + hi.x) * 0.5, (lo.y + hi.y) * 0.5);
    const double x0 = std::floor((c.x - extent) / step) * step, y0 = std::floor((c.y - extent) / step) * step;
    const int n = static_cast<int>(2.0 * extent / step) + 1;
    const double x1 = x0 + n * step, y1 = y0 + n * step;
    auto grid = std::make_shared<std::vector<float>>();
    const auto put = [&](double x, double y) {
      const glm::vec3 p(glm::dvec3(x, y, lo.z) - origin_);
      grid->insert(grid->end(), {p.x, p.y, p.z});
    };
    for (int i = 0; i <= n; ++i) {
      const double x = x0 + i * step, y = y0 + i * step;
      put(x, y0), put(x, y1), put(x0, y), put(x1, y);
    }
    grid_ = std::move(grid);
    if (!framed_) frame_all();
  }
}

void PreviewView::frame_all() {
  if (!mesh_ || mesh_->empty()) return;
  camera_.frame(glm::vec3(mesh_->min - origin_), glm::vec3(mesh_->max - origin_));
  framed_ = true;
  stale_ = true;
}

void PreviewView::request(int width, int height) {
  if (!stale_ && wireframe == drawn_wireframe_ && anchors == drawn_anchors_ && width == drawn_w_ && height == drawn_h_) return;
  stale_ = false;
  drawn_wireframe_ = wireframe;
  drawn_anchors_ = anchors;
  drawn_w_ = width;
  drawn_h_ = height;
  const glm::mat4 mvp = camera_.projection(static_cast<float>(width) / static_cast<float>(height)) * camera_.view();
  renderer_->request({mesh_, grid_, mvp, width, height, wireframe, anchors});
}

void PreviewView::draw() {
  ImGui::Checkbox("Wireframe", &wireframe);
  ImGui::SameLine();
  ImGui::SameLine();
  ImGui::Checkbox("Anchors", &anchors);
  ImGui::SameLine();
  if (ImGui::Button("Frame")) frame_all();
  if (mesh_) {
    ImGui::SameLine();
    ImGui::TextDisabled("%zu meshes, %zu faces", mesh_->meshes, mesh_->faces);
    if (mesh_->instances) {
      ImGui::SameLine();
      ImGui::TextDisabled("%zu placed", mesh_->instances);
    }
    if (!mesh_->anchors.empty()) {
      ImGui::SameLine();
      const std::size_t absent = mesh_->absent_anchors();
      if (absent) ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "%zu anchors, %zu absent", mesh_->anchors.size(), absent);
      else ImGui::TextDisabled("%zu anchors", mesh_->anchors.size());
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("The Anchors tab below lists them, with why the absent ones are absent.");
    }
    // Legend, above the image so its swatches never mix with the rendered pixels.
    for (const TagSummary& t : mesh_->tags) {
      ImGui::SameLine();
      ImGui::ColorButton(t.name.c_str(), ImVec4(t.color.r, t.color.g, t.color.b, 1.0f), ImGuiColorEditFlags_NoTooltip, ImVec2(12, 12));
      ImGui::SameLine(0, 3);
      ImGui::Text("%s", t.name.c_str());
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%zu faces, %.1f m2", t.faces, t.area);
    }
  }
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const int w = std::max(static_cast<int>(avail.x), 16), h = std::max(static_cast<int>(avail.y), 16);
  const ImVec2 corner = ImGui::GetCursorScreenPos();
  if (renderer_->take_finished()) ++renders_;
  request(w, h);
  // The last finished image, at the panel's size (stretched while one of the new size is drawn).
  if (texture()) ImGui::Image(reinterpret_cast<ImTextureID>(texture()), ImVec2(static_cast<float>(w), static_cast<float>(h)), ImVec2(0, 1), ImVec2(1, 0));
  else ImGui::Dummy(ImVec2(static_cast<float>(w), static_cast<float>(h)));
  image_x = corner.x;
  image_y = corner.y;
  image_w = static_cast<float>(w);
  image_h = static_cast<float>(h);
  if (ImGui::IsItemHovered()) {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.MouseWheel != 0) {
      camera_.zoom(io.MouseWheel);
      stale_ = true;
    }
    if (ImGui::IsMouseDragging(ImGuiMouseButton_Middle) || (io.KeyShift && ImGui::IsMouseDragging(ImGuiMouseButton_Left))) {
      camera_.pan(io.MouseDelta.x, io.MouseDelta.y, static_cast<float>(h));
      stale_ = true;
    } else if (ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
      camera_.orbit(io.MouseDelta.x, io.MouseDelta.y);
      stale_ = true;
    }
  }
}

}  // namespace procex::studio
