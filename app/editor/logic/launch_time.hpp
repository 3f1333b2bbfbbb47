// How long ago the process was launched, for the editor's load figures (time to the first frame,
// to the scene shown). Counted from the process's start as the kernel records it, so an
// execve() of the same process (a re-launch with another environment) does not reset it.
// GUI-free.
#pragma once

namespace pl {

// Milliseconds since the process started (10 ms resolution); where /proc cannot tell, since
// this library was loaded.
double ms_since_launch();

}  // namespace pl
