#pragma once
/// The guard between a plugin's code and the host (docs/plugins.md, "What the host checks").
///
/// Design note: every fracturer and stress model a command uses, built-in or a plugin's, is wrapped in
/// an object of the host's own that calls it and checks what comes back before anything else sees it: every exception (of any
/// type) and every null becomes that algorithm's error, every result passes check_fracture_output or
/// check_stress_output, and every message from the plugin is cut to one printable line. Callers then
/// treat a plugin's fault as the algorithm's failed result (a failed cell, a refused fracture), never
/// as the process's. Crashes and hangs are not caught here: `grid --timeout` runs cells in a child.

#include "algorithms/registry/registries.h"

#include <string>

namespace shatter {

/// Wraps every factory of `staged` so that what they create is guarded as above; a factory that
/// throws or gives a null is an error naming the algorithm. Called once on the program's own
/// registrations (run_cli) and once on each plugin's as it is loaded.
void guard_registrations(Registries& staged);

/// `text` as one printable line of at most `limit` bytes: control characters become spaces, a longer
/// text is cut and ends in "...". For messages that come from outside code.
std::string one_printable_line(const std::string& text, std::size_t limit = 400);

}  // namespace shatter
