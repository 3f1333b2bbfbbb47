#include "app/editor/editor_windows.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "render/legend.hpp"
#include "render/palette.hpp"
#include "render/point_key.hpp"
#include "render/text.hpp"

namespace pl {

namespace {

ImU32 rgba(const Rgb& c, float a = 1) {
  return ImGui::ColorConvertFloat4ToU32(ImVec4(c[0], c[1], c[2], a));
}

// Windows that show figures and never take the mouse or the focus.
constexpr ImGuiWindowFlags kReadout =
    ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoSavedSettings |
    ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoMove;

}  // namespace

void PointKeyImage::update(const SceneRenderer& renderer, double ui_scale, double pixel_scale) {
  if (texture_ && scale_ == ui_scale && pixel_scale_ == pixel_scale) return;
  // Labels the size of the interface's text (the key's unit is a 10 px font).
  const double text_scale = ImGui::GetFontSize() / kFontPixelsPerScale * pixel_scale / ui_scale;
  const Image key =
      render_point_key(renderer, point_key_layout(PointKeyEntries::all(), text_scale, pixel_scale));
  scale_ = ui_scale;
  pixel_scale_ = pixel_scale;
  width_ = key.width;
  height_ = key.height;
  texture_.emplace();
  GLint previous = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous);
  glBindTexture(GL_TEXTURE_2D, texture_->id());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width_, height_, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               key.rgba.data());
  glBindTexture(GL_TEXTURE_2D, GLuint(previous));
}

void draw_status_bar(const StatusLine& status, const StatusFigures& f, float s) {
  const ImGuiIO& io = ImGui::GetIO();
  const float h = ImGui::GetFrameHeight() + 6 * s;
  ImGui::SetNextWindowPos(ImVec2(0, io.DisplaySize.y - h));
  ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, h));
  ImGui::PushStyleColor(ImGuiCol_WindowBg, ImGui::GetStyleColorVec4(ImGuiCol_MenuBarBg));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(8 * s, 3 * s));
  ImGui::Begin("##status", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoBringToFrontOnFocus);
  ImGui::Text("%s  |  eval %.1f ms (%s)  |  frame %.1f ms  |  settle %.0f ms  |  %zu selected",
              f.tool.c_str(), status.eval_ms, f.coarse ? "coarse" : "fine",
              status.median_frame_ms(), status.settle_ms, f.selected);
  if (!f.under.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("  |  %s", f.under.c_str());
  }
  if (!f.drawing.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("  |  %s", f.drawing.c_str());
  }
  if (!f.plane.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("  |  %s", f.plane.c_str());
  }
  const std::string message = status.message();
  if (!message.empty()) {
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(1.0f, 0.7f, 0.4f, 1), "  |  %s", message.c_str());
  }
  ImGui::End();
  ImGui::PopStyleVar();
  ImGui::PopStyleColor();
}

bool draw_help_window(bool* open, const ActionRegistry& actions, PointKeyImage& key,
                      const SceneRenderer& renderer, float s) {
  const ImGuiIO& io = ImGui::GetIO();
  // Inside the window at any size: a margin all round, below the menu bar; what does not fit
  // wraps (descriptions) or scrolls (the window).
  const float margin = std::min(24 * s, io.DisplaySize.x * 0.02f);
  const float top = ImGui::GetFrameHeight() + margin;
  const ImVec2 most(std::max(1.0f, io.DisplaySize.x - 2 * margin),
                    std::max(1.0f, io.DisplaySize.y - top - margin - ImGui::GetFrameHeight()));
  ImGui::SetNextWindowPos(ImVec2(margin, top), ImGuiCond_Always);
  ImGui::SetNextWindowSizeConstraints(ImVec2(std::min(most.x, 260 * s), std::min(most.y, 160 * s)),
                                      most);
  ImGui::SetNextWindowSize(ImVec2(std::min(most.x, 920 * s), most.y), ImGuiCond_Appearing);
  ImGui::SetNextWindowBgAlpha(1.0f);
  if (!ImGui::Begin("Mouse and keys", open,
                    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse |
                        ImGuiWindowFlags_NoMove)) {
    ImGui::End();
    return false;
  }
  const bool focused = ImGui::IsWindowFocused(ImGuiFocusedFlags_RootAndChildWindows);
  const double fb_scale = io.DisplayFramebufferScale.x > 0 ? io.DisplayFramebufferScale.x : 1.0;
  key.update(renderer, s, fb_scale * s);
  const ImVec2 key_size(float(key.width() / fb_scale), float(key.height() / fb_scale));
  const float gap = ImGui::GetStyle().ItemSpacing.x * 3;
  // The key beside the list when there is room for both, else above it.
  const bool beside = ImGui::GetContentRegionAvail().x > key_size.x + gap + 420 * s;

  auto draw_key = [&] {
    ImGui::TextUnformatted("Control points");
    if (key.texture())
      ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(key.texture())), key_size);
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + std::max(key_size.x, 220 * s));
    ImGui::TextDisabled(
        "Filled: editable (drag them). Rings: derived from the network, "
        "they follow it. Faded: behind a surface. Selection in orange, "
        "warnings in yellow.");
    ImGui::PopTextWrapPos();
  };
  if (beside) {
    ImGui::BeginGroup();
    draw_key();
    ImGui::EndGroup();
    ImGui::SameLine(0, gap);
  } else {
    draw_key();
    ImGui::Spacing();
  }

  ImGui::BeginGroup();
  const std::vector<HelpRow> rows = help_rows(actions, mouse_help());
  // The keys column as wide as its widest entry (at most 40 % of the width); descriptions wrap
  // in what is left.
  const float avail = ImGui::GetContentRegionAvail().x;
  float keys_width = 0;
  for (const HelpRow& r : rows)
    keys_width = std::max(keys_width, ImGui::CalcTextSize(r.keys.c_str()).x);
  keys_width = std::min(keys_width, avail * 0.4f);
  if (ImGui::BeginTable("help", 2, ImGuiTableFlags_RowBg, ImVec2(avail, 0))) {
    ImGui::TableSetupColumn("keys", ImGuiTableColumnFlags_WidthFixed, keys_width);
    ImGui::TableSetupColumn("what", ImGuiTableColumnFlags_WidthStretch);
    for (const HelpRow& r : rows) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextWrapped("%s", r.keys.c_str());
      ImGui::TableNextColumn();
      ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
      ImGui::TextWrapped("%s", r.what.c_str());
      ImGui::PopStyleColor();
    }
    ImGui::EndTable();
  }
  ImGui::EndGroup();
  ImGui::End();
  return focused;
}

void draw_probe_window(const ProbeHit& p, const std::string& name, std::optional<double> distance,
                       float s) {
  // A small read-out that follows the cursor, offset so it never hides what is probed, kept
  // inside the window.
  const ImGuiIO& io = ImGui::GetIO();
  ImVec2 at(io.MousePos.x + 18 * s, io.MousePos.y + 18 * s);
  const ImVec2 pivot(at.x + 260 * s > io.DisplaySize.x ? 1.0f : 0.0f,
                     at.y + 120 * s > io.DisplaySize.y ? 1.0f : 0.0f);
  if (pivot.x > 0) at.x = io.MousePos.x - 18 * s;
  if (pivot.y > 0) at.y = io.MousePos.y - 18 * s;
  ImGui::SetNextWindowPos(at, ImGuiCond_Always, pivot);
  ImGui::SetNextWindowBgAlpha(1.0f);
  ImGui::Begin("##probe", nullptr, kReadout | ImGuiWindowFlags_AlwaysAutoResize);
  if (!name.empty()) ImGui::TextDisabled("%s", name.c_str());
  if (distance) ImGui::Text("d   %10.4g   (GB - Gregory)", *distance);
  ImGui::Text("p   %8.4f %8.4f %8.4f", p.position.x, p.position.y, p.position.z);
  ImGui::Text("n   %8.4f %8.4f %8.4f", p.normal.x, p.normal.y, p.normal.z);
  ImGui::Text("k1  %10.4g   k2 %10.4g", p.k1, p.k2);
  ImGui::Text("K   %10.4g   H  %10.4g", p.gaussian, p.mean);
  ImGui::End();
}

void draw_legend_column(const ViewRect& column, std::span<const LegendSpec> legends, float s) {
  if (legends.empty() || column.width < 1) return;
  ImGui::SetNextWindowPos(ImVec2(float(column.x), float(column.y)));
  ImGui::SetNextWindowSize(ImVec2(float(column.width), float(column.height)));
  const Rgb bg = palette::kPanel;
  ImGui::PushStyleColor(ImGuiCol_WindowBg, ImVec4(bg[0] * 0.93f, bg[1] * 0.93f, bg[2] * 0.94f, 1));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::Begin("##legends", nullptr, kReadout | ImGuiWindowFlags_NoBringToFrontOnFocus);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImU32 ink = rgba(palette::kInk), frame = rgba(palette::kPanelFrame);
  const float pad = 8 * s, line = ImGui::GetTextLineHeight();
  const float x0 = float(column.x) + pad, x1 = float(column.x + column.width) - pad;
  // Each legend gets an equal share of the height: title, then the bar with five ticks.
  const float share = float(column.height) / float(legends.size());
  for (std::size_t i = 0; i < legends.size(); ++i) {
    const LegendSpec& l = legends[i];
    const float top = float(column.y) + share * float(i) + pad;
    const float bottom = top + std::min(share - 2 * pad, 360 * s);
    dl->AddRectFilled(ImVec2(x0, top), ImVec2(x1, bottom), rgba(palette::kPanel), 4 * s);
    dl->AddRect(ImVec2(x0, top), ImVec2(x1, bottom), frame, 4 * s);
    // The title wraps within the panel.
    const float wrap = x1 - x0 - 2 * pad;
    const ImVec2 title = ImGui::CalcTextSize(l.title.c_str(), nullptr, false, wrap);
    dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(), ImVec2(x0 + pad, top + pad), ink,
                l.title.c_str(), nullptr, wrap);
    const float y0 = top + 2 * pad + title.y + line * 0.5f, y1 = bottom - pad - line * 0.5f;
    if (y1 - y0 < 2 * line) continue;  // no room for a bar: the title alone
    const float bx0 = x0 + pad, bx1 = bx0 + 14 * s;
    constexpr int kSteps = 64;
    for (int k = 0; k < kSteps; ++k) {
      // Top is hi: t runs from 1 at the top to 0 at the bottom.
      const Rgb a = color_map(1 - double(k) / kSteps), b = color_map(1 - double(k + 1) / kSteps);
      dl->AddRectFilledMultiColor(ImVec2(bx0, y0 + (y1 - y0) * k / kSteps),
                                  ImVec2(bx1, y0 + (y1 - y0) * (k + 1) / kSteps), rgba(a), rgba(a),
                                  rgba(b), rgba(b));
    }
    dl->AddRect(ImVec2(bx0, y0), ImVec2(bx1, y1), frame);
    const double ticks[5] = {l.range.hi, l.range.hi / 2, 0, l.range.lo / 2, l.range.lo};
    for (int k = 0; k < 5; ++k) {
      const float y = y0 + (y1 - y0) * k / 4;
      dl->AddLine(ImVec2(bx1, y), ImVec2(bx1 + 4 * s, y), ink);
      dl->AddText(ImVec2(bx1 + 7 * s, y - line * 0.5f), ink, format_tick(ticks[k]).c_str());
    }
  }
  ImGui::End();
  ImGui::PopStyleVar();
  ImGui::PopStyleColor();
}

void draw_busy_window(const std::string& what, double seconds, float s) {
  const ImGuiIO& io = ImGui::GetIO();
  const float bottom = ImGui::GetFrameHeight() + 6 * s;  // above the status bar
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y - bottom - 12 * s),
                          ImGuiCond_Always, ImVec2(0.5f, 1.0f));
  ImGui::SetNextWindowBgAlpha(1.0f);
  ImGui::Begin("##busy", nullptr, kReadout | ImGuiWindowFlags_AlwaysAutoResize);
  // A spinner: an arc turning once a second (the loop wakes at least four times a second).
  const float r = ImGui::GetTextLineHeight() * 0.4f;
  const ImVec2 c(ImGui::GetCursorScreenPos().x + r + 2 * s,
                 ImGui::GetCursorScreenPos().y + ImGui::GetTextLineHeight() * 0.5f);
  const float a0 = float(seconds * 2 * M_PI);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->PathArcTo(c, r, a0, a0 + float(1.5 * M_PI), 24);
  dl->PathStroke(ImGui::GetColorU32(ImGuiCol_CheckMark), 0, 2.5f * s);
  ImGui::Dummy(ImVec2(2 * r + 4 * s, ImGui::GetTextLineHeight()));
  ImGui::SameLine();
  ImGui::Text("%s  %.0f s", what.c_str(), seconds);
  ImGui::End();
}

}  // namespace pl
