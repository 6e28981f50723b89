#include "app/studio/ui/preview_renderer.h"

#include <GL/glcorearb.h>
#include <GLFW/glfw3.h>

#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <utility>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "app/studio/editor/thread_cpu.h"

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

}  // namespace

// The renderer thread's objects: in its own context (vertex arrays and
// framebuffers belong to one context), the mesh uploaded when a new one comes.
struct PreviewRenderer::Scene {
  GLuint mesh_program = 0, line_program = 0;
  GLuint edge_vao = 0, edge_vbo = 0, grid_vao = 0, grid_vbo = 0;
  GLsizei edge_vertices = 0, grid_vertices = 0;
  ShadedBuffer mesh, marker_triangles, marker_lines;
  std::vector<std::unique_ptr<ShadedBuffer>> placed;  // one per distinct placed mesh
  std::vector<GLuint> textures;                       // PreviewMesh::textures, uploaded
  std::shared_ptr<const PreviewMesh> uploaded;
  std::shared_ptr<const std::vector<float>> uploaded_grid;

  Scene() {
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
  ~Scene() {
    if (!textures.empty()) glDeleteTextures(static_cast<GLsizei>(textures.size()), textures.data());
    glDeleteProgram(mesh_program);
    glDeleteProgram(line_program);
    for (GLuint* v : {&edge_vao, &grid_vao}) glDeleteVertexArrays(1, v);
    for (GLuint* b : {&edge_vbo, &grid_vbo}) glDeleteBuffers(1, b);
  }
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  static void upload(GLuint vbo, const std::vector<float>& data) {
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
  }

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

  void set_mesh(const std::shared_ptr<const PreviewMesh>& m) {
    if (m == uploaded) return;
    uploaded = m;
    static const std::vector<float> kNone;
    static const std::vector<PreviewRange> kNoRanges;
    static const std::vector<PreviewTexture> kNoTextures;
    upload_textures(m ? m->textures : kNoTextures);
    mesh.upload(m ? m->vertices : kNone, m ? m->ranges : kNoRanges);
    marker_triangles.upload(m ? m->marker_triangles : kNone);
    marker_lines.upload(m ? m->marker_lines : kNone);
    placed.clear();
    if (m)
      for (const PreviewInstances& group : m->placed) {
        auto& buffer = placed.emplace_back(std::make_unique<ShadedBuffer>());
        buffer->upload(group.vertices, group.ranges);
        buffer->upload_instances(group.transforms);
      }
    upload(edge_vbo, m ? m->edge_points : kNone);
    edge_vertices = m ? static_cast<GLsizei>(m->edge_points.size() / 3) : 0;
  }

  void set_grid(const std::shared_ptr<const std::vector<float>>& g) {
    if (g == uploaded_grid) return;
    uploaded_grid = g;
    static const std::vector<float> kNone;
    upload(grid_vbo, g ? *g : kNone);
    grid_vertices = g ? static_cast<GLsizei>(g->size() / 3) : 0;
  }
};

PreviewRenderer::PreviewRenderer(GLFWwindow* window, std::function<void()> finished) : finished_callback_(std::move(finished)) {
  // A window never shown, for its context; the other hints are the studio window's (OpenGL 3.3 core).
  glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
  context_ = glfwCreateWindow(16, 16, "3D preview context", nullptr, window);
  glfwWindowHint(GLFW_VISIBLE, GLFW_TRUE);
  if (!context_) throw std::runtime_error("cannot make an OpenGL context for the 3D preview");
  thread_ = std::thread([this] { run(); });
}

PreviewRenderer::~PreviewRenderer() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_one();
  thread_.join();
  glfwDestroyWindow(context_);
}

void PreviewRenderer::request(PreviewShot shot) {
  {
    std::lock_guard lock(mutex_);
    pending_ = std::move(shot);
  }
  wake_.notify_one();
}

bool PreviewRenderer::take_finished() {
  std::lock_guard lock(mutex_);
  if (finished_ < 0) return false;
  if (shown_ >= 0) {
    // Every command of the window's that sampled the image given back comes before this fence.
    images_[shown_].released = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    glFlush();
  }
  shown_ = std::exchange(finished_, -1);
  shown_texture_ = images_[shown_].texture;
  shown_w_ = images_[shown_].width;
  shown_h_ = images_[shown_].height;
  wake_.notify_one();
  return true;
}

bool PreviewRenderer::busy() const {
  std::lock_guard lock(mutex_);
  return pending_.has_value() || drawing_ || finished_ >= 0;
}

double PreviewRenderer::cpu_ms() const {
  std::lock_guard lock(mutex_);
  return cpu_ms_;
}

PreviewRenderer::Progress PreviewRenderer::progress() const {
  std::lock_guard lock(mutex_);
  return {drawing_, images_finished_};
}

void PreviewRenderer::run() {
  name_this_thread("procex-preview");
  glfwMakeContextCurrent(context_);
  scene_ = std::make_unique<Scene>();
  for (Image& image : images_) {
    glGenFramebuffers(1, &image.fbo);
    glGenTextures(1, &image.texture);
    glGenRenderbuffers(1, &image.depth);
  }
  std::unique_lock lock(mutex_);
  for (;;) {
    int target = -1;
    // An image neither shown nor finished and waiting to be: one finished and not taken is
    // replaced by a newer one only when it is not the last one free.
    wake_.wait(lock, [&] {
      if (stop_) return true;
      if (!pending_) return false;
      for (int i = 0; i < 2 && target < 0; ++i)
        if (i != shown_ && i != finished_) target = i;
      return target >= 0;
    });
    if (stop_) break;
    const PreviewShot shot = std::move(*pending_);
    pending_.reset();
    drawing_ = true;
    Image& image = images_[target];
    GLsync released = std::exchange(image.released, nullptr);
    lock.unlock();
    const double start = thread_cpu_ms();
    if (released) {
      while (glClientWaitSync(released, 0, 1000000000) == GL_TIMEOUT_EXPIRED) {
      }
      glDeleteSync(released);
    }
    draw(shot, image);
    glFinish();  // the window samples the image only once it is complete
    const double used = thread_cpu_ms() - start;
    lock.lock();
    cpu_ms_ += used;
    drawing_ = false;
    finished_ = target;
    ++images_finished_;
    lock.unlock();
    finished_callback_();
    lock.lock();
  }
  lock.unlock();
  scene_.reset();
  for (Image& image : images_) {
    glDeleteFramebuffers(1, &image.fbo);
    glDeleteTextures(1, &image.texture);
    glDeleteRenderbuffers(1, &image.depth);
    if (image.released) glDeleteSync(image.released);
  }
  glFinish();
  glfwMakeContextCurrent(nullptr);
}

void PreviewRenderer::draw(const PreviewShot& shot, Image& image) {
  Scene& s = *scene_;
  s.set_mesh(shot.mesh);
  s.set_grid(shot.grid);
  const int width = shot.width, height = shot.height;
  if (width != image.width || height != image.height) {
    image.width = width;
    image.height = height;
    glBindTexture(GL_TEXTURE_2D, image.texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, image.fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, image.texture, 0);
    glBindRenderbuffer(GL_RENDERBUFFER, image.depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, image.depth);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, image.fbo);
  glViewport(0, 0, width, height);
  glClearColor(0.16f, 0.17f, 0.20f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  const glm::mat4& mvp = shot.mvp;
  glUseProgram(s.line_program);
  glUniformMatrix4fv(glGetUniformLocation(s.line_program, "mvp"), 1, GL_FALSE, glm::value_ptr(mvp));
  glUniform4f(glGetUniformLocation(s.line_program, "color"), 0.30f, 0.30f, 0.30f, 1.0f);
  glBindVertexArray(s.grid_vao);
  glDrawArrays(GL_LINES, 0, s.grid_vertices);

  glUseProgram(s.mesh_program);
  glUniformMatrix4fv(glGetUniformLocation(s.mesh_program, "mvp"), 1, GL_FALSE, glm::value_ptr(mvp));
  glUniform1i(glGetUniformLocation(s.mesh_program, "image"), 0);
  glActiveTexture(GL_TEXTURE0);
  const GLint textured = glGetUniformLocation(s.mesh_program, "textured");
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 1.0f);  // keeps the wireframe in front of its own faces
  s.mesh.draw(GL_TRIANGLES, s.textures, textured);
  for (const auto& group : s.placed) group->draw(GL_TRIANGLES, s.textures, textured);
  glBindTexture(GL_TEXTURE_2D, 0);
  glDisable(GL_POLYGON_OFFSET_FILL);
  if (shot.anchors) {  // over everything: a placed window would hide the anchor it sits on
    glDisable(GL_DEPTH_TEST);
    s.marker_triangles.draw(GL_TRIANGLES, s.textures, textured);
    s.marker_lines.draw(GL_LINES, s.textures, textured);
    glEnable(GL_DEPTH_TEST);
  }
  if (shot.wireframe) {
    glUseProgram(s.line_program);
    glUniform4f(glGetUniformLocation(s.line_program, "color"), 0.05f, 0.05f, 0.05f, 1.0f);
    glBindVertexArray(s.edge_vao);
    glDrawArrays(GL_LINES, 0, s.edge_vertices);
  }
  glBindVertexArray(0);
  glUseProgram(0);
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace procex::studio
