// The PRP values the engine needs (gpp_file_ext, drill cycle names, subroutine numbering).
// A minimal `key = value` reader, as the engine issue allows until the prp/ library lands; it keeps
// every line of the file so that nothing is lost, and reports malformed lines with their position.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace postproc {

class PrpSettings {
public:
  PrpSettings() = default;
  // Throws toolpath::InputError (file:line:col) for a line that is not `key = value`.
  static PrpSettings load(const std::string& path);
  static PrpSettings parse(std::string_view text, const std::string& file_name);

  // The last value of `key` (case-insensitive), trimmed; nullopt when absent.
  std::optional<std::string> value(std::string_view key) const;
  // Every value of a repeated key, in order (`drill_type = ...` lines).
  std::vector<std::string> values(std::string_view key) const;

  // The output file extension (`gpp_file_ext`), empty when absent.
  std::string file_extension() const { return value("gpp_file_ext").value_or(""); }
  // The user names of the drill cycles (first word of each `drill_type` line).
  std::vector<std::string> drill_type_names() const;
  // The parameters each cycle declares after its Y/N flag (`drill_type = Peck Peck Y Delay` -> Delay).
  std::vector<std::pair<std::string, std::vector<std::string>>> drill_cycle_parameters() const;

private:
  std::vector<std::pair<std::string, std::string>> entries_;
};

}  // namespace postproc
