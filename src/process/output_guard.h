// An output must never be one of the script's own inputs: `-o shader.frag`
// or `--dump 6=grid.png` over the texture it reads would destroy a
// student's work with no way back (issue 30). Checked after the plan has
// resolved every file, before anything is drawn or written.
#pragma once
#include <string>

#include "plan/plan.h"

namespace glimmer {

// The input `output` would overwrite (the script, a shader, an image or a
// model, as the script names it), or "" when it names none. Files are
// compared as the system sees them (device and inode), so another spelling,
// a symlink or a hard link to an input is caught too.
std::string inputOverwrittenBy(const Plan& plan, const std::string& output);

// The usage error when `file` (given with `option`: "-o", "--dump 6") is one
// of the script's inputs: "glimmer: error: -o f.frag: that is 'f.frag', which
// the script reads; write the picture under another name" (`what`: "picture",
// "sheet"); "" when it is not.
// Also refused: a folder, a FIFO, a device, or a name under /dev, /proc or
// /sys (open() on a FIFO blocks; "/dev/full.png" is never a picture). A frame
// pattern ("frame%d.png") is checked for each of its first `frames` names.
std::string overwritesAnInput(const Plan& plan, const std::string& option, const std::string& file,
                              const std::string& what, int frames = 1);

// The same refusal as the message's text alone ("save f.frag: that is
// 'f.frag', which ..."), for a front end that words it itself (view's status
// line); "" when `file` may be written.
std::string outputRefusal(const Plan& plan, const std::string& option, const std::string& file, const std::string& what,
                          int frames = 1);

// Why `file` is no file to write a picture to ("a FIFO ...", "under /dev/,
// not a file"), or "" when it may be one.
std::string notAFileToWrite(const std::string& file);

}  // namespace glimmer
