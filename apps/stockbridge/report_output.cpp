#include "report_output.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::cli {

CLI::Option* add_report_option(CLI::App& command, std::optional<std::string>& path, const std::string& what) {
  return command.add_option("--report", path,
                            "Also write a self-contained HTML report (" + what + "; printable on A4), e.g. report.html");
}

void check_report_path(const std::optional<std::string>& path, const std::string& option) {
  if (!path) return;
  const std::filesystem::path p(*path);
  const std::string extension = p.extension().string();
  if (extension != ".html" && extension != ".htm") {
    throw InvalidParameter(
        fmt::format("{} = '{}': expected an HTML file name ending in .html", option, printable(*path)));
  }
  const std::filesystem::path folder = p.parent_path().empty() ? std::filesystem::path(".") : p.parent_path();
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error)) {
    throw InvalidParameter(fmt::format("{} = '{}': the folder '{}' does not exist", option, printable(*path),
                                       printable(folder.string())));
  }
}

}  // namespace stockbridge::cli
