// Wall-clock time for the solve's timing infos (MC_INFO_TIME_*) and its log messages.
#pragma once
#include <chrono>

namespace mc {

inline double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Adds the elapsed time since construction to `sum` when it goes out of scope.
struct Stopwatch {
  double &sum;
  double start = now();
  explicit Stopwatch(double &s) : sum(s) {}
  ~Stopwatch() { sum += now() - start; }
};

}  // namespace mc
