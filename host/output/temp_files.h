// clrender's temporary files: their names, and the removal of those a crashed run left.
//
// Every output is first written under a temporary name in its final folder (rename() is
// atomic only within one file system). The name is short and fixed in form,
// ".clrender-<host id>-<pid>-<n>.tmp" (and "<that>.log" for the video encoder's log), so that
// it fits wherever the final name fits, and so that a later run can recognise and remove the
// leftovers of a run that was killed (SIGKILL, a power cut) before it could clean up.
#pragma once

#include <functional>
#include <string>

namespace clr {

// How many temporary names are tried for one file before its creation is refused.
constexpr int kMostTempNameTries = 16;

// A fresh temporary path in the folder of `final_path` (never derived from its name).
std::string temp_path_in_folder_of(const std::string& final_path);

// Makes a temporary file in the folder of `final_path`: `create(temp_path)` makes it (with
// O_EXCL) and returns whether it did, errno set when not. The first name is the usual one;
// while the name is taken (EEXIST), unpredictable ones follow, since the usual names can be
// guessed (the pid is public, the counter starts at 0) and another user who may write into
// the folder could take them all first. Returns the path made, or "" with errno set.
std::string create_under_temp_name(const std::string& final_path,
                                   const std::function<bool(const std::string& temp_path)>& create);

// Why create_under_temp_name() failed with `error_number`, to follow "FINAL_PATH: ". Where
// every name was taken, it says so: "File exists" alone would blame the final name.
std::string temp_creation_failure(int error_number);

// 8 lowercase hex digits naming this machine and process-id namespace: a process id in a
// temporary name means something only where the same processes are visible.
const std::string& temp_host_id();

// True when `file_name` is a temporary name of this host's form whose process is no longer
// alive (kill(pid, 0) fails with ESRCH): nobody will ever finish or remove that file.
bool is_stale_temp_name(const std::string& file_name);

// Removes the stale temporary files (regular files only) directly inside `folder`; nothing
// else is touched and errors are ignored (another run may be removing the same files).
// Returns how many were removed.
int sweep_stale_temp_files(const std::string& folder);

// Readies the folder of `final_path` for output before anything renders: sweeps it, then
// creates and removes one temporary file there, so that a missing, read-only or full folder
// fails now and not after a long render. Throws OutputError naming `final_path`.
void prepare_output_folder(const std::string& final_path);

// The same test without the sweep, for a run that must change nothing (--check, --plan): a
// temporary file is created and removed again, so that the check fails exactly when a render
// would. Throws OutputError naming `final_path`.
void probe_output_folder(const std::string& final_path);

}  // namespace clr
