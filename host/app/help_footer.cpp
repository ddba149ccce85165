#include "app/help_footer.h"

namespace clr {

// Every variable a getenv() in host/ reads, but the PATH and HOME every program reads, is
// listed here: tests/app/install_test.cpp compares the two lists.
std::string help_footer() {
    return R"(Commands:
  clrender view SCENE [options]  Render the scene live in the browser: fly the camera, record and
                                 export camera paths (clrender view --help)
  clrender compare SCENE IMAGE   Render the scene and compare it with IMAGE pixel by pixel
                                 (clrender compare --help)

Environment:
  CLRENDER_DEVICE            Default for -d, the OpenCL device
  CLRENDER_CACHE_DIR         Folder of the program, image, mesh and mesh tree caches, or 'off'; default
                             $XDG_CACHE_HOME/clrender, else ~/.cache/clrender
  XDG_CACHE_HOME             See CLRENDER_CACHE_DIR
  CLRENDER_PROGRAM_STORE     Folder of programs built ahead of need, or 'off'; default
                             share/clrender/programs of the install
  CLRENDER_FFMPEG            Video encoder program; default ffmpeg on PATH
  CLRENDER_FFPROBE           Video checker program; default the ffprobe beside the encoder,
                             else on PATH
  CLRENDER_ENCODER_TIMEOUT   Seconds an encoder may make no progress; default 60
  CLRENDER_IMAGE_MEMORY_MIB  Limit on a scene's decoded images in MiB; default 2048
  POCL_CACHE_DIR             PoCL's kernel cache; default $XDG_CACHE_HOME/pocl, else
                             ~/.cache/pocl: named when PoCL cannot write it
  POCL_KERNEL_CACHE          0: PoCL keeps no kernel cache (then its folder is not needed)
  XDG_RUNTIME_DIR            clrender view: folder for the page that opens the browser (the
                             user's own); default the temporary folder
  CLRENDER_STOP_WITH_PARENT  Set by clrender view for its video's render: the process id
                             whose end stops the render (SIGTERM)
  CLRENDER_LINKS_REPLACED    Set by clrender view for its video's render (1): a symbolic link
                             at an output's name is replaced, not written through
  CLRENDER_SCENE_ON_STDIN    Set by clrender view for its video's render (1): the scene's text
                             is read from standard input; its path only names it

Exit status:
  0    Done
  1    Usage: an unknown or malformed option, contradictory options, a frame out of range
  2    The scene file or an input image: missing, unreadable or invalid
  3    OpenCL: no such device, a failed build or run, the device's memory exhausted
  4    An output: cannot be written, would replace an input, a full disk, a failed encoder
  5    Internal error: a bug in clrender; please report it
  6    Out of memory: the machine's memory or threads ran out
  7    clrender compare: the render and the image differ beyond the tolerance
  128+N  Interrupted by signal N: 130 for SIGINT (Ctrl-C), 143 for SIGTERM, 129 for SIGHUP

Examples:
  clrender scene.json                          Render scene.png in the current folder
  clrender scene.json -o big.png --size 1920x1080 --spp 16
                                               Larger, with 16 samples per pixel
  clrender path.json -o 'f_%04d.png' --video path.mp4 --frames 0-99
                                               Frames 0 to 99 of a camera path, and their video
  clrender compare scene.json mine.png -o diff.png
                                               Compare a render with mine.png (clrender compare --help)
)";
}

}  // namespace clr
