#include "app/studio/ui/preview_view.h"

#include <GL/glcorearb.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "app/studio/editor/thread_cpu.h"
#include "app/studio/ui/offscreen_image.h"

namespace procex::studio {

namespace {

const char* kMeshVs = R"(#version 330 core
layout(location = 0) in vec3 pos;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 color;
// Placed meshes: one per instance; the buildings' own triangles get the identity (kIdentityModel).
layout(location = 3) in mat4 model;
layout(location = 7) in mat3 normal_matrix;
layout(location = 10) in vec2 uv;
uniform mat4 mvp;
out vec3 v_normal;
out vec3 v_color;
out vec2 v_uv;
void main() {
  v_normal = normal_matrix * normal;
  v_color = color;
  v_uv = uv;
  gl_Position = mvp * model * vec4(pos, 1.0);
})";

constexpr GLuint kModelAttribute = 3, kNormalMatrixAttribute = 7, kUvAttribute = 10;

// Lighting only scales the tag colour (times the material's texture, sampled
// at the face's texture coordinates, where it has one), so its chromaticity
// stays recognisable.
const char* kMeshFs = R"(#version 330 core
in vec3 v_normal;
in vec3 v_color;
in vec2 v_uv;
uniform bool textured;
uniform sampler2D image;
out vec4 frag;
void main() {
  vec3 n = normalize(v_normal);
  float key = max(dot(n, normalize(vec3(0.4, 0.6, 0.8))), 0.0);
  float fill = max(dot(n, normalize(vec3(-0.6, -0.3, 0.2))), 0.0);
  vec3 base = textured ? v_color * texture(image, v_uv).rgb : v_color;
  frag = vec4(base * (0.35 + 0.55 * key + 0.2 * fill), 1.0);
})";

const char* kLineVs = R"(#version 330 core
layout(location = 0) in vec3 pos;
uniform mat4 mvp;
void main() { gl_Position = mvp * vec4(pos, 1.0); })";

const char* kLineFs = R"(#version 330 core
uniform vec4 color;
out vec4 frag;
void main() { frag = color; })";

GLuint compile(GLenum kind, const char* src) {
  GLuint s = glCreateShader(kind);
  glShaderSource(s, 1, &src, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[1024];
    glGetShaderInfoLog(s, sizeof log, nullptr, log);
    std::fprintf(stderr, "procex-studio: shader does not compile: %s\n", log);
  }
  return s;
}

GLuint program(const char* vs, const char* fs) {
  GLuint p = glCreateProgram();
  GLuint v = compile(GL_VERTEX_SHADER, vs), f = compile(GL_FRAGMENT_SHADER, fs);
  glAttachShader(p, v);
  glAttachShader(p, f);
  glLinkProgram(p);
  glDeleteShader(v);
  glDeleteShader(f);
  return p;
}

}  // namespace

// Triangles or lines in PreviewMesh's vertex layout, and for placed meshes
// the instances' transforms.
struct ShadedBuffer {
  GLuint vao = 0, vbo = 0, instance_vbo = 0;
  GLsizei vertices = 0, instances = 0;

  ShadedBuffer() {
    glGenVertexArrays(1, &vao);
    glGenBuffers(1, &vbo);
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    const GLsizei stride = static_cast<GLsizei>(PreviewMesh::kFloatsPerVertex * sizeof(float));
    for (GLuint a = 0; a < 3; ++a) {
      glEnableVertexAttribArray(a);
      glVertexAttribPointer(a, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(std::uintptr_t{a} * 3 * sizeof(float)));
    }
    glEnableVertexAttribArray(kUvAttribute);
    glVertexAttribPointer(kUvAttribute, 2, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(9 * sizeof(float)));
    glBindVertexArray(0);
  }
  ~ShadedBuffer() {
    glDeleteVertexArrays(1, &vao);
    glDeleteBuffers(1, &vbo);
    if (instance_vbo) glDeleteBuffers(1, &instance_vbo);
  }
  ShadedBuffer(const ShadedBuffer&) = delete;
  ShadedBuffer& operator=(const ShadedBuffer&) = delete;

  // ranges: runs of the vertices by texture (none: all of them, untextured).
  void upload(const std::vector<float>& data, const std::vector<PreviewRange>& by_texture = {}) {
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    vertices = static_cast<GLsizei>(data.size() / PreviewMesh::kFloatsPerVertex);
    ranges = by_texture;
    if (ranges.empty()) ranges.push_back({0, static_cast<std::size_t>(vertices), -1});
  }
  // Makes this an instanced buffer: the model and normal matrices become per-instance attributes.
  void upload_instances(const std::vector<float>& transforms) {
    glBindVertexArray(vao);
    if (!instance_vbo) glGenBuffers(1, &instance_vbo);
    glBindBuffer(GL_ARRAY_BUFFER, instance_vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(transforms.size() * sizeof(float)), transforms.data(), GL_STATIC_DRAW);
    const GLsizei stride = static_cast<GLsizei>(PreviewInstances::kFloatsPerInstance * sizeof(float));
    for (GLuint c = 0; c < 4; ++c) {
      glEnableVertexAttribArray(kModelAttribute + c);
      glVertexAttribPointer(kModelAttribute + c, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(std::uintptr_t{c} * 4 * sizeof(float)));
      glVertexAttribDivisor(kModelAttribute + c, 1);
    }
    for (GLuint c = 0; c < 3; ++c) {
      glEnableVertexAttribArray(kNormalMatrixAttribute + c);
      glVertexAttribPointer(kNormalMatrixAttribute + c, 3, GL_FLOAT, GL_FALSE, stride,
                            reinterpret_cast<const void*>((16 + std::uintptr_t{c} * 3) * sizeof(float)));
      glVertexAttribDivisor(kNormalMatrixAttribute + c, 1);
    }
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    instances = static_cast<GLsizei>(transforms.size() / PreviewInstances::kFloatsPerInstance);
  }
  // Each range with its texture bound (`textures`: GL names by PreviewMesh::textures' index) and the
  // program's `textured` uniform (at `textured_uniform`) set to match.
  void draw(GLenum mode, const std::vector<GLuint>& textures, GLint textured_uniform) const {
    glBindVertexArray(vao);
    // Attributes without arrays take these constants: the identity.
    if (!instance_vbo) {
      for (GLuint c = 0; c < 4; ++c) glVertexAttrib4f(kModelAttribute + c, c == 0, c == 1, c == 2, c == 3);
      for (GLuint c = 0; c < 3; ++c) glVertexAttrib3f(kNormalMatrixAttribute + c, c == 0, c == 1, c == 2);
    }
    for (const PreviewRange& r : ranges) {
      const bool textured = r.texture >= 0 && static_cast<std::size_t>(r.texture) < textures.size();
      glUniform1i(textured_uniform, textured);
      if (textured) glBindTexture(GL_TEXTURE_2D, textures[static_cast<std::size_t>(r.texture)]);
      const auto first = static_cast<GLint>(r.first);
      const auto count = static_cast<GLsizei>(r.count);
      if (instance_vbo)
        glDrawArraysInstanced(mode, first, count, instances);
      else
        glDrawArrays(mode, first, count);
    }
    glUniform1i(textured_uniform, 0);
  }
  std::vector<PreviewRange> ranges;
};

struct PreviewView::Gl {
  GLuint mesh_program = 0, line_program = 0;
  GLuint edge_vao = 0, edge_vbo = 0, grid_vao = 0, grid_vbo = 0;
  GLsizei edge_vertices = 0, grid_vertices = 0;
  ShadedBuffer mesh, marker_triangles, marker_lines;
  std::vector<std::unique_ptr<ShadedBuffer>> placed;  // one per distinct placed mesh
  std::vector<GLuint> textures;                       // PreviewMesh::textures, uploaded
  OffscreenImage image{true};

  // Repeating, mipmapped: a brick texture seen from afar blends to its mean, not to noise.
  void upload_textures(const std::vector<PreviewTexture>& images) {
    if (!textures.empty()) glDeleteTextures(static_cast<GLsizei>(textures.size()), textures.data());
    textures.assign(images.size(), 0);
    if (images.empty()) return;
    glGenTextures(static_cast<GLsizei>(textures.size()), textures.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (std::size_t i = 0; i < images.size(); ++i) {
      glBindTexture(GL_TEXTURE_2D, textures[i]);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, images[i].width, images[i].height, 0, GL_RGBA, GL_UNSIGNED_BYTE, images[i].rgba.data());
      glGenerateMipmap(GL_TEXTURE_2D);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glBindTexture(GL_TEXTURE_2D, 0);
  }

  Gl() {
    mesh_program = program(kMeshVs, kMeshFs);
    line_program = program(kLineVs, kLineFs);
    for (auto [vao, vbo] : {std::pair{&edge_vao, &edge_vbo}, std::pair{&grid_vao, &grid_vbo}}) {
      glGenVertexArrays(1, vao);
      glGenBuffers(1, vbo);
      glBindVertexArray(*vao);
      glBindBuffer(GL_ARRAY_BUFFER, *vbo);
      glEnableVertexAttribArray(0);
      glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
    }
    glBindVertexArray(0);
  }
  ~Gl() {
    if (!textures.empty()) glDeleteTextures(static_cast<GLsizei>(textures.size()), textures.data());
    glDeleteProgram(mesh_program);
    glDeleteProgram(line_program);
    for (GLuint* v : {&edge_vao, &grid_vao}) glDeleteVertexArrays(1, v);
    for (GLuint* b : {&edge_vbo, &grid_vbo}) glDeleteBuffers(1, b);
  }
  void upload(GLuint vbo, const std::vector<float>& data) {
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
  }
};

PreviewView::PreviewView() : gl_(std::make_unique<Gl>()) {}
PreviewView::~PreviewView() = default;

std::uintptr_t PreviewView::texture() const { return gl_->image.texture(); }

void PreviewView::look_from(float yaw_deg, float pitch_deg) {
  camera_.yaw = yaw_deg;
  camera_.pitch = pitch_deg;
  stale_ = true;
}

void PreviewView::set_mesh(std::shared_ptr<const PreviewMesh> mesh) {
  if (mesh == mesh_) return;
  const double cpu_start = thread_cpu_ms();
  mesh_ = std::move(mesh);
  stale_ = true;
  static const std::vector<float> kNone;
  static const std::vector<PreviewRange> kNoRanges;
  static const std::vector<PreviewTexture> kNoTextures;
  gl_->upload_textures(mesh_ ? mesh_->textures : kNoTextures);
  gl_->mesh.upload(mesh_ ? mesh_->vertices : kNone, mesh_ ? mesh_->ranges : kNoRanges);
  gl_->marker_triangles.upload(mesh_ ? mesh_->marker_triangles : kNone);
  gl_->marker_lines.upload(mesh_ ? mesh_->marker_lines : kNone);
  gl_->placed.clear();
  if (mesh_)
    for (const PreviewInstances& group : mesh_->placed) {
      auto& buffer = gl_->placed.emplace_back(std::make_unique<ShadedBuffer>());
      buffer->upload(group.vertices, group.ranges);
      buffer->upload_instances(group.transforms);
    }
  gl_->upload(gl_->edge_vbo, mesh_ ? mesh_->edge_points : kNone);
  gl_->edge_vertices = mesh_ ? static_cast<GLsizei>(mesh_->edge_points.size() / 3) : 0;
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
    std::vector<float> grid;
    const auto put = [&](double x, double y) {
      const glm::vec3 p(glm::dvec3(x, y, lo.z) - origin_);
      grid.insert(grid.end(), {p.x, p.y, p.z});
    };
    for (int i = 0; i <= n; ++i) {
      const double x = x0 + i * step, y = y0 + i * step;
      put(x, y0), put(x, y1), put(x0, y), put(x1, y);
    }
    gl_->upload(gl_->grid_vbo, grid);
    gl_->grid_vertices = static_cast<GLsizei>(grid.size() / 3);
    if (!framed_) frame_all();
  }
  upload_cpu_ms_ += thread_cpu_ms() - cpu_start;
}

void PreviewView::frame_all() {
  if (!mesh_ || mesh_->empty()) return;
  camera_.frame(glm::vec3(mesh_->min - origin_), glm::vec3(mesh_->max - origin_));
  framed_ = true;
  stale_ = true;
}

void PreviewView::render(int width, int height) {
  if (!stale_ && wireframe == drawn_wireframe_ && anchors == drawn_anchors_ && width == gl_->image.width() && height == gl_->image.height()) return;
  stale_ = false;
  ++renders_;
  const double cpu_start = thread_cpu_ms();
  drawn_wireframe_ = wireframe;
  drawn_anchors_ = anchors;
  GLint previous_fbo = 0, previous_viewport[4];
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous_fbo);
  glGetIntegerv(GL_VIEWPORT, previous_viewport);
  gl_->image.resize(width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, gl_->image.framebuffer());
  glViewport(0, 0, width, height);
  glClearColor(0.16f, 0.17f, 0.20f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  const glm::mat4 mvp = camera_.projection(static_cast<float>(width) / static_cast<float>(height)) * camera_.view();
  glUseProgram(gl_->line_program);
  glUniformMatrix4fv(glGetUniformLocation(gl_->line_program, "mvp"), 1, GL_FALSE, glm::value_ptr(mvp));
  glUniform4f(glGetUniformLocation(gl_->line_program, "color"), 0.30f, 0.30f, 0.30f, 1.0f);
  glBindVertexArray(gl_->grid_vao);
  glDrawArrays(GL_LINES, 0, gl_->grid_vertices);

  glUseProgram(gl_->mesh_program);
  glUniformMatrix4fv(glGetUniformLocation(gl_->mesh_program, "mvp"), 1, GL_FALSE, glm::value_ptr(mvp));
  glUniform1i(glGetUniformLocation(gl_->mesh_program, "image"), 0);
  glActiveTexture(GL_TEXTURE0);
  const GLint textured = glGetUniformLocation(gl_->mesh_program, "textured");
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 1.0f);  // keeps the wireframe in front of its own faces
  gl_->mesh.draw(GL_TRIANGLES, gl_->textures, textured);
  for (const auto& group : gl_->placed) group->draw(GL_TRIANGLES, gl_->textures, textured);
  glBindTexture(GL_TEXTURE_2D, 0);
  glDisable(GL_POLYGON_OFFSET_FILL);
  if (anchors) {  // over everything: a placed window would hide the anchor it sits on
    glDisable(GL_DEPTH_TEST);
    gl_->marker_triangles.draw(GL_TRIANGLES, gl_->textures, textured);
    gl_->marker_lines.draw(GL_LINES, gl_->textures, textured);
    glEnable(GL_DEPTH_TEST);
  }
  if (wireframe) {
    glUseProgram(gl_->line_program);
    glUniform4f(glGetUniformLocation(gl_->line_program, "color"), 0.05f, 0.05f, 0.05f, 1.0f);
    glBindVertexArray(gl_->edge_vao);
    glDrawArrays(GL_LINES, 0, gl_->edge_vertices);
  }
  glBindVertexArray(0);
  glUseProgram(0);
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous_fbo));
  glViewport(previous_viewport[0], previous_viewport[1], previous_viewport[2], previous_viewport[3]);
  render_cpu_ms_ += thread_cpu_ms() - cpu_start;
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
  render(w, h);
  ImGui::Image(reinterpret_cast<ImTextureID>(texture()), ImVec2(static_cast<float>(w), static_cast<float>(h)),
               ImVec2(0, 1), ImVec2(1, 0));
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
