#include "ui/panels/file_browser.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "core/mesh/mesh_import.h"
#include "ui/app/session.h"
#include "ui/document/review_queue.h"

namespace sagrid::ui {

namespace fs = std::filesystem;

FileBrowser::FileBrowser() { setDirectory(fs::current_path()); }

void FileBrowser::setDirectory(const fs::path& dir) {
  m_dir = fs::absolute(dir).lexically_normal();
  std::snprintf(m_pathInput, sizeof m_pathInput, "%s", m_dir.string().c_str());
  m_refresh = true;
}

void FileBrowser::refresh() {
  m_folders.clear();
  m_meshes.clear();
  m_error.clear();
  std::error_code ec;
  for (const auto& item : fs::directory_iterator(m_dir, ec)) {
    const std::string name = item.path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    if (item.is_directory(ec))
      m_folders.push_back(item.path());
    else if (isMeshFile(item.path()))
      m_meshes.push_back(item.path());
  }
  if (ec) m_error = m_dir.string() + ": " + ec.message();
  std::sort(m_folders.begin(), m_folders.end());
  std::sort(m_meshes.begin(), m_meshes.end());
  m_refresh = false;
}

void FileBrowser::draw(Session& session) {
  if (session.showFileBrowser) m_visible = true, session.showFileBrowser = false, m_refresh = true;
  if (!m_visible) return;
  if (m_refresh) refresh();
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowSize(ImVec2(560, 440), ImGuiCond_Appearing);
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing,
                          ImVec2(0.5f, 0.5f));
  if (!ImGui::Begin("Open", &m_visible, ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  ImGui::SetNextItemWidth(-70);
  if (ImGui::InputText("##path", m_pathInput, sizeof m_pathInput,
                       ImGuiInputTextFlags_EnterReturnsTrue)) {
    const fs::path typed(m_pathInput);
    std::error_code ec;
    if (fs::is_directory(typed, ec))
      setDirectory(typed);
    else if (fs::is_regular_file(typed, ec))
      session.openPaths({typed}), m_visible = false;
  }
  ImGui::SameLine();
  if (ImGui::Button("Up")) setDirectory(m_dir.parent_path());
  if (!m_error.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", m_error.c_str());
  ImGui::BeginChild("entries", ImVec2(0, -36), true);
  fs::path enter;
  for (const auto& folder : m_folders) {
    if (ImGui::Selectable(("[dir]  " + folder.filename().string()).c_str(), false,
                          ImGuiSelectableFlags_AllowDoubleClick) &&
        ImGui::IsMouseDoubleClicked(0)) {
      enter = folder;
    }
  }
  for (const auto& mesh : m_meshes) {
    if (ImGui::Selectable(mesh.filename().string().c_str(), false,
                          ImGuiSelectableFlags_AllowDoubleClick) &&
        ImGui::IsMouseDoubleClicked(0)) {
      session.openPaths({mesh});
      m_visible = false;
    }
  }
  ImGui::EndChild();
  if (!enter.empty()) setDirectory(enter);
  if (ImGui::Button("Open this folder as the review queue")) {
    session.openPaths({m_dir});
    m_visible = false;
  }
  ImGui::SameLine();
  if (ImGui::Button("Cancel")) m_visible = false;
  ImGui::End();
}

}  // namespace sagrid::ui
