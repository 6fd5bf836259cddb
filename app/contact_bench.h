#pragma once
// `weft bench --contact`: the collision stage's cost for a sheet draped on a sphere, with and
// without self-collision.
#include <string>

namespace weft::app {

struct ContactBenchOptions {
  int resolution = 64;      // grid vertices per side
  int warmup = 90;          // untimed steps: the sheet falls onto the ball and drapes (1.5 s)
  int steps = 30;           // timed steps per repeat
  int repeats = 3;          // the median over every timed step of every repeat is reported
  int threads = 1;
  std::string csv = "out/bench/contact.csv";
};

int runContactBench(const ContactBenchOptions& options);

}  // namespace weft::app
