#include "output/summary_json.hpp"

#include <cmath>

namespace coremodal {

Json summary_head(std::string_view command, const std::string &case_name,
                  const std::string &case_file,
                  const std::string &description) {
  Json head;
  head["schema_version"] = kSummarySchemaVersion;
  head["program"] = "coremodal " COREMODAL_VERSION;
  head["command"] = std::string(command);
  head["case"] = Json{
      {"name", case_name}, {"file", case_file}, {"description", description}};
  return head;
}

Json number_or_null(double value) {
  return std::isfinite(value) ? Json(value) : Json(nullptr);
}

Json string_array(const std::vector<std::string> &items) {
  Json a = Json::array();
  for (const std::string &item : items)
    a.push_back(item);
  return a;
}

Json safe_web_speed_json(const RollSpeeds &speeds) {
  if (!speeds.given())
    return Json{{"not_given", speeds.not_given}};
  Json rows = Json::array();
  for (const SafeSpeed &s : speeds.safe)
    rows.push_back(Json{{"safe", s.safe},
                        {"v_safe_m_s", s.v_safe_m_s},
                        {"v_safe_m_min", 60 * s.v_safe_m_s}});
  return Json{
      {"f1_hz", speeds.f1_hz}, {"dp_m", speeds.dp_m}, {"safe_web_speed", rows}};
}

std::string json_text(const Json &document) {
  // Replace invalid UTF-8 (a case file's name is the user's) rather than throw.
  return document.dump(2, ' ', false,
                       nlohmann::json::error_handler_t::replace) +
         "\n";
}

} // namespace coremodal
