#pragma once
// Runs the stockbridge program as a user would and captures what it says.

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>
#include <sys/wait.h>

#include <unistd.h>

namespace stockbridge::testing {

/// The shipped example damper (D. Sauter's verification damper), which most command tests run.
inline const std::string kDamperExample = std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/sauter2003.toml";

struct CliResult {
  int exit_code = -1;
  std::string out;
  std::string err;

  int stderr_lines() const {
    int lines = 0;
    for (char ch : err) lines += ch == '\n';
    return lines;
  }
};

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

/// The lines of a text, without their line ends.
inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// The cells of a CSV line; a quoted cell may hold ',' (its quotes kept).
inline std::vector<std::string> csv_cells(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (const char ch : line) {
    if (ch == '"') quoted = !quoted;
    if (ch == ',' && !quoted) {
      cells.emplace_back();
    } else {
      cells.back() += ch;
    }
  }
  return cells;
}

/// A CSV text's cell of row `row` (1: the first after the header) in column `name`.
inline std::string csv_cell(const std::string& csv, std::size_t row, const std::string& name) {
  const std::vector<std::string> rows = lines_of(csv);
  const std::vector<std::string> header = csv_cells(rows.at(0)), cells = csv_cells(rows.at(row));
  const auto column = std::find(header.begin(), header.end(), name);
  if (column == header.end()) return "(no column " + name + ")";
  return cells.at(static_cast<std::size_t>(column - header.begin()));
}

/// A fresh, empty directory for one test's files.
inline std::filesystem::path scratch_directory(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() /
             ("stockbridge-test-" + std::to_string(::getpid()) + "-" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// Runs `stockbridge <arguments>` (a shell-quoted string) in `directory`.
inline CliResult run_cli(const std::string& arguments, const std::filesystem::path& directory) {
  const auto out = directory / "stdout.txt";
  const auto err = directory / "stderr.txt";
  const std::string command = "cd '" + directory.string() + "' && '" + STOCKBRIDGE_CLI + "' " + arguments +
                              " > '" + out.string() + "' 2> '" + err.string() + "' < /dev/null";
  const int status = std::system(command.c_str());
  CliResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = read_text(out);
  result.err = read_text(err);
  return result;
}

/// The records of a journal (its lines after the first; 0 while there is none).
inline int journal_records(const std::filesystem::path& journal) {
  const std::string text = read_text(journal);
  int lines = 0;
  for (const char c : text) lines += c == '\n';
  return lines > 0 ? lines - 1 : 0;
}

/// Runs `stockbridge <arguments>` in `directory` in the background (stdout to
/// run.log, stderr to run.err) and sends it `signal` once `ready()` holds (or five
/// minutes have passed); its wait status.
inline int run_cli_stopped_when(const std::string& arguments, const std::filesystem::path& directory,
                                const std::function<bool()>& ready, int signal) {
  const std::string command = "cd '" + directory.string() + "' && exec '" + STOCKBRIDGE_CLI + "' " + arguments +
                              " > run.log 2> run.err";
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(5);
  while (!ready() && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ::kill(pid, signal);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}

/// The hidden temporary file a streamed output is written to beside `output`
/// (io::AtomicFileWriter's), or an empty path while there is none.
inline std::filesystem::path temporary_beside(const std::filesystem::path& dir, const std::string& output) {
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().filename().string().starts_with("." + output + ".tmp-")) return entry.path();
  }
  return {};
}

/// run_cli_stopped_when the temporary file of the streamed `output` holds some rows
/// (4 KiB): the wait status, and whether that file was seen before the signal.
struct StreamedStop {
  int status = 0;
  bool seen = false;
};
inline StreamedStop run_cli_stopped_streaming(const std::string& arguments, const std::filesystem::path& directory,
                                              const std::string& output, int signal) {
  StreamedStop out;
  out.status = run_cli_stopped_when(
      arguments, directory,
      [&] {
        const std::filesystem::path temporary = temporary_beside(directory, output);
        std::error_code ec;
        out.seen = !temporary.empty() && std::filesystem::file_size(temporary, ec) >= 4096 && !ec;
        return out.seen;
      },
      signal);
  return out;
}

/// run_cli_stopped_when `journal` holds `records` records.
inline int run_cli_stopped(const std::string& arguments, const std::filesystem::path& directory,
                           const std::filesystem::path& journal, int records, int signal) {
  return run_cli_stopped_when(arguments, directory, [&] { return journal_records(journal) >= records; }, signal);
}

}  // namespace stockbridge::testing
