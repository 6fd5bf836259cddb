#pragma once
// The subcommands of `weft`, one file each. Every command registers its options on the CLI11 app
// and returns what to run once the command line has been parsed; main() only dispatches.
#include <functional>

#include <CLI/CLI.hpp>

namespace weft::app {

// Process exit codes, the same for every command (scripts and tests rely on them).
enum ExitCode : int {
  kExitOk = 0,
  kExitFailure = 1,    // could not write output, or an internal error
  kExitBadInput = 2,   // bad scene, preset, mesh or command line
  kExitNonFinite = 3,  // the simulation became non-finite or failed its health check (sim/health_check.h)
};

struct Command {
  CLI::App* cli = nullptr;   // the subcommand, to ask whether it was chosen
  std::function<int()> run;  // runs it with the parsed options; returns an ExitCode
};

Command addRunCommand(CLI::App& app);
Command addValidateCommand(CLI::App& app);
Command addBenchCommand(CLI::App& app);
Command addEditCommand(CLI::App& app);
Command addStudyAnalyzeCommand(CLI::App& app);
Command addStudyVideosCommand(CLI::App& app);
Command addGuessCommand(CLI::App& app);
Command addGalleryCommand(CLI::App& app);

// `weft` with no subcommand: `weft edit` on the default scene.
int editDefaultScene();

}  // namespace weft::app
