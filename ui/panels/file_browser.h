// File -> Open: a small in-app browser (folders first, meshes shown, others hidden) that opens a
// file or a whole folder as the review queue. Keeps only its own navigation state.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sagrid::ui {

class Session;

class FileBrowser {
 public:
  FileBrowser();
  void open() { m_visible = true, m_refresh = true; }
  void draw(Session& session);
  void setDirectory(const std::filesystem::path& dir);

 private:
  void refresh();
  bool m_visible = false;
  bool m_refresh = true;
  std::filesystem::path m_dir;
  std::vector<std::filesystem::path> m_folders, m_meshes;
  char m_pathInput[1024] = {};
  std::string m_error;
};

}  // namespace sagrid::ui
