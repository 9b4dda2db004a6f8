// Progress messages of a solve, sent to the host's callback (mc_set_log_callback). The sink
// belongs to one model (no global state) and formats a message only when a callback is set.
#pragma once
#include "mortarcontact.h"

namespace mc {

struct ProgressLog {
  mc_log_fn fn = nullptr;
  void *user_data = nullptr;

  bool enabled() const { return fn != nullptr; }
  // printf-style one-line message. The callback is host code behind a C interface and must
  // return normally. Should a C++ exception come out of it anyway, it is dropped here rather
  // than unwound through the solver - which works where host and library share one unwinder
  // (static library). The shared library is linked with -static-libgcc: its personality
  // routine cannot handle the host's unwind context and the process aborts before the catch.
  void operator()(mc_log_level level, const char *format, ...) const noexcept
      __attribute__((format(printf, 3, 4)));
};

}  // namespace mc
