// stockbridge: command-line front end of the stockbridge library.
// Exit status: 0 success, 2 bad input or options (one line on stderr, nothing
// written), 3 computed but some points did not converge (file written, flagged).

#include <cstdio>
#include <exception>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "commands.hpp"
#include "invocation.hpp"
#include "misspellings.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/version.hpp"

namespace {

/// A message as one line (the library's messages are; CLI11's and the standard
/// library's may not be), so that every failure is exactly one line on stderr.
std::string one_line(std::string text) {
  for (char& ch : text) {
    if (ch == '\n' || ch == '\r') ch = ' ';
  }
  return stockbridge::printable(text, text.size());
}

}  // namespace

int main(int argc, char** argv) {
  using namespace stockbridge;
  CLI::App app{"stockbridge: nonlinear impedance of Stockbridge dampers (Masing cable model)", "stockbridge"};
  app.require_subcommand(1);
  app.set_version_flag("--version", fmt::format("stockbridge {}", stockbridge::version()));
  cli::Invocation invocation(argc, argv);
  cli::add_loop_command(app, invocation);
  cli::add_cycle_command(app, invocation);
  cli::add_identify_command(app, invocation);
  cli::add_impedance_command(app, invocation);
  cli::add_response_command(app, invocation);
  cli::add_strand_command(app, invocation);
  cli::add_conductors_command(app, invocation);
  cli::add_modes_command(app, invocation);
  cli::add_span_command(app, invocation);
  cli::add_recorder_command(app, invocation);
  cli::add_design_command(app, invocation);
  cli::add_line_command(app, invocation);
  cli::add_datasheet_command(app, invocation);
  cli::add_fatigue_tests_command(app, invocation);
  cli::add_simulate_command(app, invocation);
  try {
    cli::reject_misspellings(app, argc, argv);
    app.parse(argc, argv);
    invocation.flush_warnings();
  } catch (const CLI::CallForHelp&) {
    std::fputs(app.help().c_str(), stdout);
    return cli::kSuccess;
  } catch (const CLI::CallForVersion&) {
    std::fputs((app.version() + "\n").c_str(), stdout);
    return cli::kSuccess;
  } catch (const CLI::CallForAllHelp&) {
    std::fputs(app.help("", CLI::AppFormatMode::All).c_str(), stdout);
    return cli::kSuccess;
  } catch (const CLI::ParseError& e) {
    std::fputs(fmt::format("stockbridge: {} (see stockbridge --help)\n", one_line(e.what())).c_str(), stderr);
    return cli::kBadInput;
  } catch (const UnusualValueError& e) {
    std::fputs(fmt::format("stockbridge: {} (--allow-unusual takes it as given)\n", one_line(e.what())).c_str(), stderr);
    return cli::kBadInput;
  } catch (const Error& e) {
    std::fputs(fmt::format("stockbridge: {}\n", one_line(e.what())).c_str(), stderr);
    return cli::kBadInput;
  } catch (const std::exception& e) {
    std::fputs(fmt::format("stockbridge: internal error: {}\n", one_line(e.what())).c_str(), stderr);
    return 1;
  }
  return invocation.exit_code();
}
