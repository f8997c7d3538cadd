#include "core/curation/curation_log.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/common/atomic_file.h"
#include "core/common/error.h"

namespace sagrid {

namespace {
struct Name {
  CurationAction action;
  const char* text;
};
constexpr Name kNames[] = {
    {CurationAction::Open, "open"},         {CurationAction::Look, "look"},
    {CurationAction::Accept, "accept"},     {CurationAction::AcceptAll, "accept_all"},
    {CurationAction::Drag, "drag"},         {CurationAction::Add, "add"},
    {CurationAction::Delete, "delete"},     {CurationAction::DeleteRest, "delete_rest"},
    {CurationAction::Retype, "retype"},
    {CurationAction::Category, "category"}, {CurationAction::ConfirmCategory, "confirm_category"},
    {CurationAction::CategoryKey, "category_key"},
    {CurationAction::Units, "units"},       {CurationAction::Copies, "copies"},
    {CurationAction::Extend, "extend"},
    {CurationAction::Edit, "edit"},         {CurationAction::Undo, "undo"},
    {CurationAction::Redo, "redo"},         {CurationAction::Skip, "skip"},
    {CurationAction::Navigate, "navigate"},
};

std::string isoTime(double seconds) {
  const auto whole = static_cast<std::time_t>(std::floor(seconds));
  const int millis = static_cast<int>(std::lround((seconds - std::floor(seconds)) * 1000.0)) % 1000;
  std::tm utc{};
  gmtime_r(&whole, &utc);
  char text[40];
  std::snprintf(text, sizeof text, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", utc.tm_year + 1900, utc.tm_mon + 1,
                utc.tm_mday, utc.tm_hour, utc.tm_min, utc.tm_sec, millis);
  return text;
}
}  // namespace

const char* toString(CurationAction action) {
  for (const Name& n : kNames)
    if (n.action == action) return n.text;
  return "edit";
}

std::optional<CurationAction> parseCurationAction(const std::string& text) {
  for (const Name& n : kNames)
    if (text == n.text) return n.action;
  return std::nullopt;
}

const std::vector<CurationAction>& allCurationActions() {
  static const std::vector<CurationAction> all = [] {
    std::vector<CurationAction> v;
    for (const Name& n : kNames) v.push_back(n.action);
    return v;
  }();
  return all;
}

std::string CurationLogWriter::record(const std::string& object, CurationAction action, const std::string& detail,
                                      const std::string& carriedFrom) {
  if (m_failed || m_path.empty()) return {};
  const double now =
      std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  nlohmann::json line{{"time", isoTime(now)},
                            {"seconds", std::round(now * 1000.0) / 1000.0},
                            {"object", object},
                            {"action", toString(action)},
                            {"detail", detail}};
  if (m_replayed) line["replayed"] = true;
  if (!carriedFrom.empty()) line["carried_from"] = carriedFrom;
  std::ofstream out(m_path, std::ios::app | std::ios::binary);
  out << line.dump() << '\n';
  out.flush();
  if (out) return {};
  m_failed = true;
  return m_path.string() + ": cannot append to the curation log; curation goes on without it";
}

std::vector<CurationEvent> readCurationLog(const std::filesystem::path& path) {
  std::istringstream lines(readFileBytes(path));
  std::vector<CurationEvent> events;
  std::size_t number = 0;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::string where = "line " + std::to_string(number);
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(line);
    } catch (const nlohmann::json::exception&) {
      throw FileError(path, where + " is not JSON (a curation log has one event per line)");
    }
    if (!j.is_object() || !j.contains("seconds") || !j["seconds"].is_number() || !j.contains("action") ||
        !j["action"].is_string() || !j.contains("object") || !j["object"].is_string()) {
      throw FileError(path, where + " lacks \"seconds\" (number), \"object\" or \"action\" (text)");
    }
    const auto action = parseCurationAction(j["action"].get<std::string>());
    if (!action) throw FileError(path, where + " has unknown action '" + j["action"].get<std::string>() + "'");
    const double seconds = j["seconds"].get<double>();
    if (!std::isfinite(seconds)) throw FileError(path, where + " has a time that is not finite");
    events.push_back({seconds, j["object"].get<std::string>(), *action,
                      j.contains("detail") && j["detail"].is_string() ? j["detail"].get<std::string>() : "",
                      j.value("replayed", false),
                      j.contains("carried_from") && j["carried_from"].is_string() ? j["carried_from"].get<std::string>() : ""});
  }
  return events;
}

}  // namespace sagrid
