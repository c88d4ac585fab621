// SPDX-License-Identifier: MIT
#include <tutti/runtime/view_stats.hpp>

#include <imgui.h>

namespace tutti::runtime {

void draw_view_stats(const ViewStats& stats, const render::WindowTarget& target, int corner) {
  const VkExtent2D view = target.render_extent();
  const VkExtent2D window = target.extent();
  ImGui::SetNextWindowPos(
      ImVec2(8.0f, corner == 0 ? 8.0f : static_cast<float>(window.height) - 8.0f),
      ImGuiCond_Always, ImVec2(0.0f, corner == 0 ? 0.0f : 1.0f));
  ImGui::SetNextWindowBgAlpha(0.6f);
  ImGui::Begin("stats", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                   ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoSavedSettings);
  ImGui::Text("frame %.1f ms (%.1f fps), average %.1f ms", 1000.0 * stats.frame_s,
              stats.frame_s > 0 ? 1.0 / stats.frame_s : 0.0, 1000.0 * stats.average_s);
  ImGui::Text("3D view %.0f %% (%ux%u of %ux%u)%s", 100.0 * target.render_scale(), view.width,
              view.height, window.width, window.height, stats.dynamic ? ", dynamic" : "");
  ImGui::Text("%s", stats.draft ? "draft: 1 sample per pixel, hard 1024² shadows"
                                : "full quality");
  ImGui::End();
}

}  // namespace tutti::runtime
