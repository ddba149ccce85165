// Small disks for the fault-injection tests: a tmpfs of a few pages, mounted inside a private
// mount namespace (`unshare -rm`: as root, or as the root of an unprivileged user namespace)
// that vanishes with the script that mounted it, so a test can fill a disk without touching
// anything outside its own folder.
#pragma once

#include <string>

namespace clr::testing {

// Whether this machine lets a test mount a tmpfs in a namespace of its own (asked once).
// Tests that need it skip, saying so, where it does not.
bool can_mount_small_disks();

// Runs `script` with `sh -e` from `folder`, inside a private mount namespace, with $CLRENDER
// naming the clrender binary and at most 120 s to finish. Returns the script's exit status,
// or -1 when it did not exit normally.
int run_in_mount_namespace(const std::string& folder, const std::string& script);

// Whether `program` is found on PATH (ffmpeg, ffprobe).
bool have_program(const std::string& program);

}  // namespace clr::testing
