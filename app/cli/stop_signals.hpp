// SIGTERM, SIGINT and SIGHUP stop a command the way an error does: the temporary file being
// written is removed (core/io/atomic_file.hpp), then the signal ends the process as it would have
// without the handler (the parent sees "killed by SIGTERM", a shell prints no extra line).
#pragma once

namespace pl {

// Installs the handlers once per process; later calls do nothing.
void remove_temporaries_on_stop_signals();

}  // namespace pl
