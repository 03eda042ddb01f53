#include "io/file_size_signal.h"

#include <csignal>

namespace io {

void failWritesPastTheFileSizeLimit() { std::signal(SIGXFSZ, SIG_IGN); }

}  // namespace io
