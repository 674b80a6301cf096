#include "app/viewer/panel_cache.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <imgui.h>

#include <backends/imgui_impl_opengl3.h>

namespace luz::app {
namespace {

constexpr gl::ColourFormat rgba8{GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, "RGBA8"};

int framebuffer_width(const ImDrawData& d) { return int(d.DisplaySize.x * d.FramebufferScale.x); }
int framebuffer_height(const ImDrawData& d) { return int(d.DisplaySize.y * d.FramebufferScale.y); }

// The pixels a command may touch: the box around its triangles' vertices, within its clip
// rectangle turned into a scissor box exactly as imgui_impl_opengl3 does, within the
// framebuffer. (A window's background is clipped to the whole screen: only its vertices say
// where it lies.) Empty when the backend skips the command.
FramebufferRect pixels_of(const ImDrawData& d, const ImDrawList& list, const ImDrawCmd& cmd) {
  const ImVec2 scale = d.FramebufferScale;
  const float height = float(framebuffer_height(d));
  const ImVec2 min((cmd.ClipRect.x - d.DisplayPos.x) * scale.x, (cmd.ClipRect.y - d.DisplayPos.y) * scale.y);
  const ImVec2 max((cmd.ClipRect.z - d.DisplayPos.x) * scale.x, (cmd.ClipRect.w - d.DisplayPos.y) * scale.y);
  if (max.x <= min.x || max.y <= min.y || cmd.ElemCount == 0) return {};
  const int sx = int(min.x), sy = int(height - max.y);
  int x0 = std::max(sx, 0), y0 = std::max(sy, 0);
  int x1 = std::min(sx + int(max.x - min.x), framebuffer_width(d));
  int y1 = std::min(sy + int(max.y - min.y), framebuffer_height(d));

  ImVec2 lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
  for (unsigned int i = 0; i < cmd.ElemCount; ++i) {
    const ImVec2 p = list.VtxBuffer[int(cmd.VtxOffset + list.IdxBuffer[int(cmd.IdxOffset + i)])].pos;
    lo = ImVec2(std::min(lo.x, p.x), std::min(lo.y, p.y));
    hi = ImVec2(std::max(hi.x, p.x), std::max(hi.y, p.y));
  }
  x0 = std::max(x0, int(std::floor((lo.x - d.DisplayPos.x) * scale.x)));
  x1 = std::min(x1, int(std::ceil((hi.x - d.DisplayPos.x) * scale.x)));
  y0 = std::max(y0, int(std::floor(height - (hi.y - d.DisplayPos.y) * scale.y)));
  y1 = std::min(y1, int(std::ceil(height - (lo.y - d.DisplayPos.y) * scale.y)));
  return {x0, y0, x1 - x0, y1 - y0};
}

bool inside(const FramebufferRect& r, const FramebufferRect& area) {
  return r.x >= area.x && r.y >= area.y && r.x + r.width <= area.x + area.width &&
         r.y + r.height <= area.y + area.height;
}

bool meets(const FramebufferRect& r, const FramebufferRect& area) {
  return r.x < area.x + area.width && area.x < r.x + r.width && r.y < area.y + area.height &&
         area.y < r.y + r.height;
}

bool inside_one(const FramebufferRect& r, std::span<const FramebufferRect> panel) {
  return std::any_of(panel.begin(), panel.end(), [&](const FramebufferRect& area) { return inside(r, area); });
}

bool meets_one(const FramebufferRect& r, std::span<const FramebufferRect> panel) {
  return std::any_of(panel.begin(), panel.end(), [&](const FramebufferRect& area) { return meets(r, area); });
}

template <class T>
void append(std::vector<std::byte>& bytes, const T* data, size_t count) {
  const size_t at = bytes.size(), size = count * sizeof(T);
  bytes.resize(at + size);
  if (size > 0) std::memcpy(bytes.data() + at, data, size);
}

// `frame` with only `lists`, for the backend.
void render(const ImDrawData& frame, std::vector<ImDrawList*>& lists) {
  if (lists.empty()) return;
  ImDrawData part = frame;
  part.CmdLists = lists.data();
  part.CmdListsCount = int(lists.size());
  part.TotalVtxCount = part.TotalIdxCount = 0;
  for (const ImDrawList* list : lists) {
    part.TotalVtxCount += list->VtxBuffer.Size;
    part.TotalIdxCount += list->IdxBuffer.Size;
  }
  ImGui_ImplOpenGL3_RenderDrawData(&part);
}

}  // namespace

bool split_lists(const ImDrawData& frame, std::span<const FramebufferRect> panel, void* font,
                 std::vector<ImDrawList*>& cached, std::vector<ImDrawList*>& live) {
  cached.clear();
  live.clear();
  bool covered = false;  // a live list reaches into the panel
  for (int i = 0; i < frame.CmdListsCount; ++i) {
    ImDrawList* list = frame.CmdLists[i];
    bool within = true, touches = false;
    for (const ImDrawCmd& cmd : list->CmdBuffer) {
      const FramebufferRect r = pixels_of(frame, *list, cmd);
      if (r.empty()) continue;
      within = within && inside_one(r, panel) && cmd.UserCallback == nullptr && cmd.TextureId == font;
      touches = touches || meets_one(r, panel);
    }
    if (within && !covered) {
      cached.push_back(list);
    } else {
      live.push_back(list);
      covered = covered || touches;
    }
  }
  return covered;
}

// Whether the cache already holds this frame's panel: the same lists, byte for byte, at the
// same size.
bool PanelCache::unchanged(const ImDrawData& frame) {
  next_.clear();
  append(next_, panel_.data(), panel_.size());
  append(next_, &frame.DisplaySize, 1);
  append(next_, &frame.FramebufferScale, 1);
  for (const ImDrawList* list : cached_) {
    const int sizes[] = {list->CmdBuffer.Size, list->VtxBuffer.Size, list->IdxBuffer.Size};
    append(next_, sizes, 3);
    for (const ImDrawCmd& cmd : list->CmdBuffer) {
      append(next_, &cmd.ClipRect, 1);
      append(next_, &cmd.TextureId, 1);
      const unsigned int offsets[] = {cmd.VtxOffset, cmd.IdxOffset, cmd.ElemCount};
      append(next_, offsets, 3);
    }
    append(next_, list->VtxBuffer.Data, size_t(list->VtxBuffer.Size));
    append(next_, list->IdxBuffer.Data, size_t(list->IdxBuffer.Size));
  }
  return target_ && width_ == framebuffer_width(frame) && height_ == framebuffer_height(frame) && next_ == drawn_;
}

void PanelCache::redraw(const ImDrawData& frame, glm::vec4 background) {
  if (!target_ || width_ != framebuffer_width(frame) || height_ != framebuffer_height(frame)) {
    width_ = framebuffer_width(frame);
    height_ = framebuffer_height(frame);
    target_.reset();  // before the next one is made: the old one's memory goes first
    target_ = std::make_unique<gl::RenderTarget>(width_, height_, rgba8);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, target_->fbo);
  glViewport(0, 0, width_, height_);
  glDisable(GL_SCISSOR_TEST);
  glClearColor(background.r, background.g, background.b, background.a);
  glClear(GL_COLOR_BUFFER_BIT);
  render(frame, cached_);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  drawn_.swap(next_);
}

bool PanelCache::prepare(ImDrawData& frame, std::span<const FramebufferRect> panel, bool window_kept) {
  frame_ = &frame;
  panel_.clear();
  for (const FramebufferRect& area : panel)
    if (!area.empty()) panel_.push_back(area);
  panel_is_ = Panel::drawn;
  reached_into_ = false;
  const bool empty = panel_.empty() || framebuffer_width(frame) <= 0 || framebuffer_height(frame) <= 0;
  if (!enabled || empty) return false;
  reached_into_ = split_lists(frame, panel_, ImGui::GetIO().Fonts->TexID, cached_, live_);
  if (cached_.empty()) return false;
  if (unchanged(frame)) {
    panel_is_ = window_kept && in_window_ && !reached_into_ ? Panel::kept : Panel::cached;
  } else if (next_ == previous_) {  // the same as last frame's: the panel has settled
    panel_is_ = Panel::redrawn;
  } else {  // changing (a plot, a hover): drawn as it is until it settles
    previous_.swap(next_);
  }
  return panel_is_ == Panel::kept;
}

void PanelCache::draw(glm::vec4 background) {
  ImDrawData& frame = *frame_;
  switch (panel_is_) {
    case Panel::drawn:
      ImGui_ImplOpenGL3_RenderDrawData(&frame);
      in_window_ = false;
      return;
    case Panel::redrawn:
      redraw(frame, background);
      ++redraws;
      break;
    case Panel::cached:
      ++hits;
      break;
    case Panel::kept:
      ++hits;
      ++kept;
      break;
  }
  if (panel_is_ != Panel::kept) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, target_->fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    for (const FramebufferRect& area : panel_) {
      const int x1 = area.x + area.width, y1 = area.y + area.height;
      glBlitFramebuffer(area.x, area.y, x1, y1, area.x, area.y, x1, y1, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }
  render(frame, live_);
  in_window_ = !reached_into_;
}

}  // namespace luz::app
