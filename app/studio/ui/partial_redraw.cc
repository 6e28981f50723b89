#include "app/studio/ui/partial_redraw.h"

#include <GL/glcorearb.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>

#include "app/studio/ui/offscreen_image.h"

namespace procex::studio {

static_assert(sizeof(ImDrawVert) == sizeof(DrawVertex) && sizeof(ImDrawIdx) == sizeof(std::uint16_t),
              "FrameDamage copies ImGui's vertices and 16-bit indices as they are");

PartialRedraw::PartialRedraw(bool in_back_buffer) : image_(in_back_buffer ? nullptr : std::make_unique<OffscreenImage>(false)) {}
PartialRedraw::~PartialRedraw() = default;

namespace {

std::vector<DrawList> copy_lists(const ImDrawData& draw) {
  std::vector<DrawList> lists;
  lists.reserve(static_cast<std::size_t>(draw.CmdListsCount));
  for (int i = 0; i < draw.CmdListsCount; ++i) {
    const ImDrawList& in = *draw.CmdLists[i];
    DrawList& out = lists.emplace_back();
    out.owner = in._OwnerName ? in._OwnerName : "";
    out.vertices.resize(static_cast<std::size_t>(in.VtxBuffer.Size));
    std::copy_n(reinterpret_cast<const DrawVertex*>(in.VtxBuffer.Data), in.VtxBuffer.Size, out.vertices.data());
    out.indices.assign(in.IdxBuffer.Data, in.IdxBuffer.Data + in.IdxBuffer.Size);
    for (const ImDrawCmd& c : in.CmdBuffer)
      out.commands.push_back({Rect{{c.ClipRect.x, c.ClipRect.y}, {c.ClipRect.z, c.ClipRect.w}}, reinterpret_cast<std::uintptr_t>(c.TextureId),
                              c.IdxOffset, c.ElemCount, c.VtxOffset});
  }
  return lists;
}

// Draws `draw` into the bound framebuffer inside r only: every command clipped to it.
void draw_within(ImDrawData* draw, const Rect& r, int height) {
  glEnable(GL_SCISSOR_TEST);
  glScissor(static_cast<GLint>(r.min.x), height - static_cast<GLint>(r.max.y), static_cast<GLsizei>(r.size().x), static_cast<GLsizei>(r.size().y));
  glClearColor(0.12f, 0.12f, 0.14f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  std::vector<ImVec4> clips;
  for (int i = 0; i < draw->CmdListsCount; ++i)
    for (ImDrawCmd& c : draw->CmdLists[i]->CmdBuffer) {
      clips.push_back(c.ClipRect);
      c.ClipRect = ImVec4(std::max(c.ClipRect.x, r.min.x), std::max(c.ClipRect.y, r.min.y), std::min(c.ClipRect.z, r.max.x),
                          std::min(c.ClipRect.w, r.max.y));
    }
  ImGui_ImplOpenGL3_RenderDrawData(draw);
  std::size_t k = 0;
  for (int i = 0; i < draw->CmdListsCount; ++i)
    for (ImDrawCmd& c : draw->CmdLists[i]->CmdBuffer) c.ClipRect = clips[k++];
}

}  // namespace

PartialRedraw::Outcome PartialRedraw::render(ImDrawData* draw, int width, int height, int back_buffer_age,
                                             const std::vector<std::uintptr_t>& redrawn_textures, bool present) {
  const Rect screen{{0.0f, 0.0f}, {static_cast<float>(width), static_cast<float>(height)}};
  // A resized image's (or back buffer's) pixels are undefined.
  if (image_ ? image_->resize(width, height) : width != width_ || height != height_) damage_.reset();
  width_ = width;
  height_ = height;
  const std::vector<Rect> damage = damage_.update(copy_lists(*draw), screen, redrawn_textures);
  Outcome outcome;
  glBindFramebuffer(GL_FRAMEBUFFER, image_ ? image_->framebuffer() : 0);
  for (const Rect& r : damage) {
    draw_within(draw, r, height);
    outcome.pixels_redrawn += static_cast<double>(r.size().x) * r.size().y;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (!image_) {  // never swapped: the back buffer holds every earlier frame, whatever its age says (copy_sub_buffer.h)
    outcome.copy_to_window = damage;
    return outcome;
  }
  // The back buffer lacks this frame's changes and those of the frames since it was last shown;
  // of unknown age, it lacks everything.
  std::vector<Rect> copy = damage;
  if (back_buffer_age <= 0 || static_cast<std::size_t>(back_buffer_age) > history_.size() + 1) {
    if (present || !damage.empty()) copy = {screen};
  } else {
    for (int i = 0; i + 1 < back_buffer_age; ++i)
      for (const Rect& r : history_[static_cast<std::size_t>(i)]) add_damage(copy, r, FrameDamage::kMaxRects);
  }
  if (!copy.empty()) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, image_->framebuffer());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    for (const Rect& r : copy) {
      // Framebuffers count rows from the bottom.
      const GLint x0 = static_cast<GLint>(r.min.x), x1 = static_cast<GLint>(r.max.x);
      const GLint y0 = height - static_cast<GLint>(r.max.y), y1 = height - static_cast<GLint>(r.min.y);
      glBlitFramebuffer(x0, y0, x1, y1, x0, y0, x1, y1, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    outcome.presented = true;
    history_.push_front(damage);
    if (history_.size() > kHistory) history_.pop_back();
  }
  return outcome;
}

}  // namespace procex::studio
