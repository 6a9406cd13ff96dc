// Writing a file so that a failure or a kill never leaves it half-written: the content goes to a
// temporary file in the same folder, which is flushed to disk (fsync) and renamed over the target
// (then the folder is synced). Readers see the old file or the complete new one, never a mix.
//
// After a SIGKILL or a power cut between writing and renaming, the temporary file
// TARGET.autoblock-tmp-PID-N[.EXT] may remain next to the target (the target itself is intact);
// the next write of the same target removes such leftovers of processes that no longer run.
#pragma once

#include <functional>
#include <vector>
#include <string>

namespace autoblock {

// Inputs:  path, the target; write, writes the whole content to the temporary path it is given
//          and returns false (or throws) when it could not.
// Outputs: the target replaced. Throws InputError when the folder is missing or the file cannot be
//          written (the temporary file is removed); exceptions of write pass through after the
//          temporary file is removed.
void write_file_atomically(const std::string& path, const std::function<bool(const std::string& temporary)>& write);

// Inputs: path. Output: the temporary files left next to path by writers that no longer run.
std::vector<std::string> stale_temporary_files(const std::string& path);

}  // namespace autoblock
