#include "support/progress_log.hpp"
#include <cstdarg>
#include <cstdio>

namespace mc {

void ProgressLog::operator()(mc_log_level level, const char *format, ...) const noexcept {
  if (!fn) return;
  char line[512];  // longer messages are cut: they are one-liners for a log, not data
  va_list args;
  va_start(args, format);
  std::vsnprintf(line, sizeof line, format, args);
  va_end(args);
  try {
    fn(user_data, level, line);
  } catch (...) {
  }
}

}  // namespace mc
