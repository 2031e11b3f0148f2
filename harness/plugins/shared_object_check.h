#pragma once
/// What a plugin file must be before the loader maps it: dlopen runs a library's initialisers and
/// touches its pages, so a file that is not a whole shared object of this machine (a truncated build,
/// a FIFO that never ends, a device, an executable, another architecture's library) is refused here
/// with one line, before anything of it is mapped or run.

#include "algorithms/core/result.h"

#include <string>

namespace shatter {

/// Error unless `path` is a regular file (after following links) holding an ELF shared object of this
/// process's class, byte order and machine whose program and section header tables and every loaded
/// segment lie inside the file. Opened without blocking, so a FIFO or device is refused, not waited
/// on; the message starts with "plugin <path>: ".
Status check_shared_object(const std::string& path);

}  // namespace shatter
