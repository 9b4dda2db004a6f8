// How the two body threads of a solve share the cores with OpenBLAS's threads
// (docs/benchmarks.md, "Threads"). Debian ships OpenBLAS built two ways, and which one is
// loaded is chosen by the system's alternatives (or LD_LIBRARY_PATH), not at build time:
// - pthread build (the default): one process-wide thread count, and one process-wide lock that
//   a threaded level-3 call holds. Two threads calling it at once with a pool of two ran 1.7 to
//   3 times slower than one after the other, so during a solve that runs both bodies at once
//   the count is lowered to one (a body asking for more would only wait on the other's calls;
//   and between the phases a call would wake a worker that spins on into the next phase), and
//   put back after;
// - OpenMP build: each call sizes its team by the calling thread's OpenMP nthreads-var, a
//   per-thread setting: each body thread sets its own, and the calling thread's is put back.
#pragma once

namespace mc {

// A scope on the calling thread around a solve that runs both bodies at once: with the pthread
// build, OpenBLAS's process-wide thread count is at most per_body inside it. It is put back on
// leaving only if it is still the value set here (another model's solve or the host may have
// set it meanwhile: theirs then stands). per_body = 0: nothing is changed.
class BlasPoolShare {
public:
  explicit BlasPoolShare(int per_body);
  ~BlasPoolShare();
  BlasPoolShare(const BlasPoolShare &) = delete;
  BlasPoolShare &operator=(const BlasPoolShare &) = delete;

private:
  int set_ = 0, restore_ = 0;
};

// A scope on one body's thread: with the OpenMP build, this thread's BLAS calls use at most
// `threads` threads inside it (its nthreads-var, put back on leaving). threads = 0: nothing.
class BlasThreadsOfThisThread {
public:
  explicit BlasThreadsOfThisThread(int threads);
  ~BlasThreadsOfThisThread();
  BlasThreadsOfThisThread(const BlasThreadsOfThisThread &) = delete;
  BlasThreadsOfThisThread &operator=(const BlasThreadsOfThisThread &) = delete;

private:
  int restore_ = 0;
};

}  // namespace mc
