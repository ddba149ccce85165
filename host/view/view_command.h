// `clrender view SCENE [options]`: the scene rendered live in the browser (docs/command-line.md,
// Viewer).
#pragma once

namespace clr {

// Runs the viewer on the arguments after `view` (argv[0] is "view") and returns the exit code;
// errors are reported as a render reports them (the scene's: exit 2, before listening).
int view_main(int argc, const char* const* argv);

}  // namespace clr
