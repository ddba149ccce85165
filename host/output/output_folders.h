// Output folders that do not exist yet: `-o frames/f_%04d.png`, `--video renders/v.mp4` or
// `--stats logs/run.json` in a fresh folder work without a mkdir first
// (docs/command-line.md, Outputs). The folders are found and checked before anything renders,
// and made only once every check of the run has passed, so that a refused run leaves no
// empty folder behind.
#pragma once

#include <string>
#include <vector>

namespace clr {

// The folders, outermost first, that must be made for a file at `final_path`; empty when its
// folder exists. Throws OutputError naming `final_path` when they could not be made: an
// existing part of the path is a file (`a.png/x.png`), or the deepest existing folder does
// not let this process create anything in it.
std::vector<std::string> missing_folders_of(const std::string& final_path);

// Makes the folders (each with mode 0777 less the umask, as mkdir -p does), in order. A
// folder that another process made meanwhile is fine (split renders start at once). Throws
// OutputError naming `for_output` when one cannot be made.
void make_output_folders(const std::vector<std::string>& folders, const std::string& for_output);

}  // namespace clr
