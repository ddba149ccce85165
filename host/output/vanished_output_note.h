// Why an output may have failed when the program that wrote it does not say: a video's folder
// removed or renamed while the video was made. ffmpeg, writing to a file it holds open, goes
// on; then its file is not found by its path ("'ffmpeg' exited successfully but wrote no
// video", or the check "cannot read it"), messages that would send the user looking at the
// encoder rather than at the folder.
#pragma once

#include <string>

namespace clr {

// "; the folder 'out' is gone: it was removed or renamed while the output was made" where the
// folder of `temporary_path` (a file clrender made there, which must still be there) no longer
// exists, "; its temporary file 'out/.clrender-...tmp' is gone: ..." where only the file went,
// else "" (also where the system cannot say).
std::string vanished_output_note(const std::string& temporary_path);

}  // namespace clr
