// `weft`: the command-line entry point. It only parses the command line and hands over to one of
// the commands (run_command.cpp, validate_command.cpp, bench_command.cpp, edit_command.cpp,
// study_analyze_command.cpp, study_videos_command.cpp, guess_command.cpp, gallery_command.cpp).
#include <exception>
#include <iostream>
#include <vector>

#include "command.h"

int main(int argc, char** argv) {
  using namespace weft::app;
  CLI::App app{"Weft: anisotropic cloth simulation with measured fabrics", "weft"};
  app.require_subcommand(0, 1);
  const std::vector<Command> commands{addRunCommand(app), addValidateCommand(app), addBenchCommand(app),
                                      addEditCommand(app), addStudyAnalyzeCommand(app),
                                      addStudyVideosCommand(app), addGuessCommand(app), addGalleryCommand(app)};
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);  // prints the message and the usage hint
    return kExitBadInput;
  }

  try {
    for (const auto& command : commands) {
      if (command.cli->parsed()) return command.run();
    }
    // No subcommand: `weft edit` on the default scene.
    return editDefaultScene();
  } catch (const std::exception& e) {
    std::cerr << "weft: internal error: " << e.what() << "\n";
    return kExitFailure;
  }
}
