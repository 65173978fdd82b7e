#include "open_dialog.h"

#include "widgets.h"

#include <imgui.h>

#include <filesystem>

namespace prism {

namespace fs = std::filesystem;

void openScene(ViewController& c, RecentFiles& recent, const std::string& path) {
  c.open(path);
  recent.add(path);
}

void drawOpenDialog(ViewController& c, OpenDialog& dialog, RecentFiles& recent, float uiScale,
                    float width, float height) {
  if (!dialog.visible) return;
  if (dialog.folder.empty())
    dialog.folder = fs::path(c.scenePath()).parent_path().lexically_normal().string();
  if (dialog.folder.empty()) dialog.folder = ".";
  ImGui::SetNextWindowPos(ImVec2(0.5f * width, 0.5f * height), ImGuiCond_Always,
                          ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(std::min(width - 40.0f, 520.0f * uiScale),
                                  std::min(height - 40.0f, 560.0f * uiScale)));
  ImGui::Begin("Open a scene (Ctrl+O)", &dialog.visible,
               ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoResize);
  std::string chosen;
  {
    const ui::Scope scope("Open"); // popped before End()
    if (!recent.paths().empty()) {
      ImGui::TextDisabled("Recent");
      const ui::Scope recentScope("recent");
      for (const std::string& p : recent.paths())
        if (ui::selectable(p.c_str())) chosen = p;
      ImGui::Separator();
    }
    ImGui::TextDisabled("%s", dialog.folder.c_str());
    {
      const ui::Scope folderScope("folder");
      ImGui::BeginChild("entries", ImVec2(0.0f, -2.0f * ImGui::GetFrameHeightWithSpacing()), true);
      if (ui::selectable("../"))
        dialog.folder = (fs::path(dialog.folder) / "..").lexically_normal();
      for (const FolderEntry& e : listSceneFolder(dialog.folder)) {
        const std::string label = e.folder ? e.name + "/" : e.name;
        if (!ui::selectable(label.c_str())) continue;
        const fs::path p = fs::path(dialog.folder) / e.name;
        if (e.folder) {
          dialog.folder = p.lexically_normal().string();
        } else {
          chosen = p.string();
        }
      }
      ImGui::EndChild();
    }
    ImGui::SetNextItemWidth(-150.0f * uiScale);
    ui::inputText("##path", &dialog.path);
    ImGui::SameLine();
    ImGui::BeginDisabled(!isSceneFile(dialog.path));
    if (ui::button("Open")) chosen = dialog.path;
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ui::button("Cancel")) dialog.visible = false;
  }
  ImGui::End();
  if (!chosen.empty()) {
    openScene(c, recent, chosen);
    dialog.visible = false;
  }
}

} // namespace prism
