// `weft guess --clips DIR --answers ANSWERS.csv --participant ID`: the blind "guess the fabric"
// step of the thesis' user study (§3.4, §4.5.2). The texture-hidden clips of DIR/manifest.json
// (`weft study-videos`) are played once each, in an order shuffled by a seed (study/guess_order.h;
// by default the participant's id), and each answer is added to ANSWERS.csv as it is given, in
// the format `weft study-analyze` reads (study/study_answers.h).
//
// A participant who stopped halfway (closed the window) continues with the clips not yet
// answered, in the same order. `--answers-from FILE` takes the answers from a file instead of a
// window (study/fabric_guess.h): for tests, and for typing in answers given on paper.
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "command.h"
#include "glfw_window.h"
#include "guess_window.h"
#include "study/clip_manifest.h"
#include "study/fabric_guess.h"
#include "study/guess_order.h"
#include "study/study_answers.h"
#include "util/echo.h"
#include "util/input_error.h"

namespace weft::app {
namespace {

namespace fs = std::filesystem;

struct GuessOptions {
  std::string clips;
  std::string answers;
  std::string participant;
  std::optional<std::uint64_t> seed;  // default: seedOfParticipant(participant)
  std::string answersFrom;            // empty: ask in a window
};

// The clips the participant has already answered in `answersFile` (none when it does not exist).
std::set<std::string> answeredClips(const std::string& answersFile, const std::string& participant) {
  std::set<std::string> answered;
  std::error_code ec;
  if (!fs::exists(answersFile, ec) || fs::file_size(answersFile, ec) == 0) return answered;
  for (const study::StudyAnswer& answer : study::readStudyAnswers(answersFile)) {
    if (answer.participant == participant) answered.insert(answer.clip);
  }
  return answered;
}

int guessFabrics(const GuessOptions& options) {
  if (options.participant.empty() || options.participant.size() > 64 ||
      options.participant.find_first_of(",\"\n\r") != std::string::npos) {
    std::cerr << "weft: guess: --participant: '" << echo(options.participant, 60)
              << "' must be 1 to 64 characters, without commas or quotes (it goes into a CSV)\n";
    return kExitBadInput;
  }
  // Everything the session needs is checked before the first clip is shown.
  std::vector<study::StudyClip> hidden;
  study::ClipManifest manifest;
  std::vector<study::FabricGuess> prepared;
  std::vector<int> toPlay;  // indices into `hidden`, in playing order
  try {
    const fs::path dir(options.clips);
    manifest = study::readClipManifest(dir / "manifest.json");
    for (const study::StudyClip& clip : manifest.clips) {
      if (clip.textured) continue;
      if (!fs::is_regular_file(dir / clip.file))
        throw InputError((dir / "manifest.json").string(), "clip " + clip.id, "its file " + clip.file + " is missing");
      hidden.push_back(clip);
    }
    if (hidden.empty())
      throw InputError((dir / "manifest.json").string(), "/clips", "no texture-hidden clips to guess");
    const std::set<std::string> answered = answeredClips(options.answers, options.participant);
    const std::uint64_t seed = options.seed.value_or(study::seedOfParticipant(options.participant));
    for (int i : study::shuffledOrder(static_cast<int>(hidden.size()), seed)) {
      if (answered.count(hidden[static_cast<std::size_t>(i)].id) == 0) toPlay.push_back(i);
    }
    if (toPlay.empty()) {
      throw InputError(options.answers, "participant " + options.participant,
                       "has already answered all " + std::to_string(hidden.size()) + " clips");
    }
    if (!options.answersFrom.empty()) {
      prepared = study::readFabricGuesses(options.answersFrom);
      if (prepared.size() != toPlay.size()) {
        throw InputError(options.answersFrom, "",
                         std::to_string(prepared.size()) + " answer(s) for " + std::to_string(toPlay.size()) +
                             " clip(s) to play; give exactly one per clip");
      }
    }
  } catch (const InputError& e) {
    std::cerr << "weft: " << e.what() << "\n";
    return kExitBadInput;
  }

  std::unique_ptr<GuessWindow> window;
  if (options.answersFrom.empty()) {
    try {
      window = std::make_unique<GuessWindow>();
    } catch (const ui::WindowUnavailable& e) {
      std::cerr << "weft: guess: cannot open a window: " << e.what()
                << " (give the answers with --answers-from FILE instead)\n";
      return kExitFailure;
    }
  }

  const int total = static_cast<int>(hidden.size());
  const int already = total - static_cast<int>(toPlay.size());
  int recorded = 0;
  try {
    for (std::size_t k = 0; k < toPlay.size(); ++k) {
      const study::StudyClip& clip = hidden[static_cast<std::size_t>(toPlay[k])];
      std::optional<study::FabricGuess> guess;
      if (window) {
        // The encoder pads odd sizes to even (mp4_encoder.h): the decoded frames have that size.
        const ClipToShow show{fs::path(options.clips) / clip.file, (manifest.width + 1) / 2 * 2,
                              (manifest.height + 1) / 2 * 2, manifest.fps, already + static_cast<int>(k), total};
        guess = window->ask(show);
        if (!guess) break;  // the window was closed; the next run continues here
      } else {
        guess = prepared[k];
      }
      study::StudyAnswer answer;
      answer.participant = options.participant;
      answer.clip = clip.id;
      answer.trueFabric = clip.fabric;
      answer.guessedFabric = guess->fabric;
      answer.guessedGroup = guess->group;
      study::appendStudyAnswers(options.answers, {answer});
      ++recorded;
    }
  } catch (const InputError& e) {
    std::cerr << "weft: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "weft: guess: " << e.what() << "\n";
    return kExitFailure;
  }
  std::cout << "recorded " << recorded << " answer(s) of participant " << options.participant << " in "
            << options.answers;
  if (already + recorded < total) std::cout << "; " << total - already - recorded << " clip(s) left for next time";
  std::cout << "\n";
  return kExitOk;
}

}  // namespace

Command addGuessCommand(CLI::App& app) {
  struct Parsed {
    GuessOptions options;
    std::uint64_t seed = 0;
    CLI::Option* seedOption = nullptr;
  };
  auto parsed = std::make_shared<Parsed>();
  GuessOptions& options = parsed->options;
  CLI::App* cli = app.add_subcommand(
      "guess", "The user study's blind step: play the texture-hidden clips once each, ask the fabric, "
               "append the answers for `weft study-analyze`");
  cli->add_option("--clips", options.clips, "Folder written by `weft study-videos` (with manifest.json)")->required();
  cli->add_option("--answers", options.answers, "Answers CSV to add to (created when missing)")->required();
  cli->add_option("--participant", options.participant, "The participant's id (no commas)")->required();
  parsed->seedOption =
      cli->add_option("--seed", parsed->seed, "Seed of the clip order (default: from the participant's id)");
  cli->add_option("--answers-from", options.answersFrom,
                  "Take the answers from FILE (one 'fabric[,group]' per line, in playing order) instead of a window");
  return {cli, [parsed] {
            GuessOptions given = parsed->options;
            if (parsed->seedOption->count() > 0) given.seed = parsed->seed;
            return guessFabrics(given);
          }};
}

}  // namespace weft::app
