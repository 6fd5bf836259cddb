#pragma once
// Wall time per named stage of the step, accumulated over the run, in the order stages first ran.
#include <chrono>
#include <string>
#include <vector>

namespace weft {

struct StageProfile {
  std::vector<std::string> names;
  std::vector<double> totalMs;

  void add(const std::string& name, double ms);
  double total() const;
  // The total of the stages whose names start with `prefix` ("contact_", "tear_").
  double totalWithPrefix(const std::string& prefix) const;
};

// Times a scope into one stage of a profile.
class StageTimer {
 public:
  StageTimer(StageProfile& profile, const char* name)
      : profile_(profile), name_(name), start_(std::chrono::steady_clock::now()) {}
  ~StageTimer() {
    const auto end = std::chrono::steady_clock::now();
    profile_.add(name_, std::chrono::duration<double, std::milli>(end - start_).count());
  }
  StageTimer(const StageTimer&) = delete;
  StageTimer& operator=(const StageTimer&) = delete;

 private:
  StageProfile& profile_;
  const char* name_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace weft
