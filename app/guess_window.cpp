#include "guess_window.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "glfw_window.h"
#include "imgui_layer.h"
#include "mp4_decoder.h"

namespace weft::app {
namespace {

using Clock = std::chrono::steady_clock;

enum class Phase { Ready, Playing, Answering };

// A GL texture the decoded frames are uploaded into, shown with ImGui::Image.
class FrameTexture {
 public:
  FrameTexture(int width, int height) : width_(width), height_(height) {
    glGenTextures(1, &id_);
    glBindTexture(GL_TEXTURE_2D, id_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  }
  ~FrameTexture() { glDeleteTextures(1, &id_); }
  FrameTexture(const FrameTexture&) = delete;
  FrameTexture& operator=(const FrameTexture&) = delete;

  void upload(const std::vector<std::uint8_t>& rgba) {
    glBindTexture(GL_TEXTURE_2D, id_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  }
  // The frame as large as fits in the space left in the current ImGui window, aspect kept.
  void show() const {
    const ImVec2 space = ImGui::GetContentRegionAvail();
    const float scale = std::min(space.x / width_, space.y / height_);
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(id_)),
                 ImVec2(width_ * scale, height_ * scale));
  }

 private:
  unsigned id_ = 0;
  int width_, height_;
};

}  // namespace

struct GuessWindow::Impl {
  ui::GlfwWindow window{ui::WindowSettings{"Weft: guess the fabric", 1100, 900, 4, true}};
  ImGuiLayer imgui{window.handle()};

  // One frame of the window around `content`, a full-window ImGui panel.
  template <typename Content>
  void frame(Content&& content) {
    window.pollEvents();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(viewport->Pos);
    ImGui::SetNextWindowSize(viewport->Size);
    ImGui::Begin("guess", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings);
    content();
    ImGui::End();
    ImGui::Render();
    window.bindDefaultFramebuffer();
    glClearColor(0.93f, 0.94f, 0.96f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    window.swapBuffers();
  }
};

GuessWindow::GuessWindow() : impl_(std::make_unique<Impl>()) {}
GuessWindow::~GuessWindow() = default;

std::optional<study::FabricGuess> GuessWindow::ask(const ClipToShow& clip) {
  Phase phase = Phase::Ready;
  std::unique_ptr<Mp4Decoder> decoder;
  FrameTexture texture(clip.width, clip.height);
  std::vector<std::uint8_t> rgba;
  Clock::time_point started;
  long long framesShown = 0;
  int fabric = -1, group = -1;
  std::optional<study::FabricGuess> answer;
  const std::string title = "Clip " + std::to_string(clip.index + 1) + " of " + std::to_string(clip.count);

  while (!answer && !impl_->window.shouldClose()) {
    if (phase == Phase::Playing) {
      // Decode up to the frame due now: a slow frame of the window skips video frames rather
      // than slowing the clip down.
      const double elapsed = std::chrono::duration<double>(Clock::now() - started).count();
      const auto due = static_cast<long long>(elapsed * clip.fps) + 1;
      bool ended = false;
      while (framesShown < due && !ended) {
        ended = !decoder->next(rgba);
        if (!ended) ++framesShown;
      }
      if (ended) {
        decoder.reset();
        phase = Phase::Answering;
      } else {
        texture.upload(rgba);
      }
    }
    impl_->frame([&] {
      ImGui::TextUnformatted(title.c_str());
      ImGui::Separator();
      if (phase == Phase::Ready) {
        ImGui::TextWrapped(
            "The clip plays once: 5 s in the wind, 5 s moved left and right, 5 s hit by a heavy ball. The "
            "cloth's texture is hidden; watch how it moves and tears. Then say which fabric it was.");
        if (ImGui::Button("Play", ImVec2(160, 40))) {
          decoder = std::make_unique<Mp4Decoder>(clip.file, clip.width, clip.height);
          started = Clock::now();
          phase = Phase::Playing;
        }
      } else if (phase == Phase::Playing) {
        texture.show();
      } else {
        ImGui::TextUnformatted("Which fabric was it?");
        for (study::Fabric f : study::kFabrics) {
          ImGui::RadioButton(std::string(study::fabricName(f)).c_str(), &fabric, study::indexOf(f));
          ImGui::SameLine();
        }
        ImGui::NewLine();
        ImGui::Spacing();
        ImGui::TextUnformatted("How elastic was it?");
        ImGui::RadioButton("stiff (stretches little)", &group, study::indexOf(study::ElasticityGroup::Stiff));
        ImGui::SameLine();
        ImGui::RadioButton("stretchy", &group, study::indexOf(study::ElasticityGroup::Stretchy));
        ImGui::Spacing();
        const bool complete = fabric >= 0 && group >= 0;
        ImGui::BeginDisabled(!complete);
        if (ImGui::Button(clip.index + 1 < clip.count ? "Next clip" : "Finish", ImVec2(160, 40)) && complete) {
          answer = study::FabricGuess{study::kFabrics[static_cast<std::size_t>(fabric)],
                                      study::kElasticityGroups[static_cast<std::size_t>(group)]};
        }
        ImGui::EndDisabled();
      }
    });
  }
  return answer;
}

}  // namespace weft::app
