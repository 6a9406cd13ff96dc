// Running a risky computation (reading untrusted files with OpenCASCADE) in a child process, so
// that a crash, an endless loop or a runaway allocation cannot take the caller down with it.
//
// The child (fork) runs with OpenCASCADE's signal handling (an access violation becomes an
// exception there), a memory limit (its current address space + 4 GiB; none under sanitizers) and
// a time budget; it is killed when its parent dies and by its own alarm, so nothing is ever left
// running. Only the calling thread exists in the child: work must not need other threads, locks
// held elsewhere or Python. When fork is unavailable, work runs in this process.
#pragma once

#include <functional>
#include <string>

namespace autoblock {

// Inputs:  work, computes a text (or throws; its message becomes the error); what, names the input
//          in messages about the child; budget_seconds (> 0) before the child is killed.
// Outputs: work's text. Throws InputError: work's message (InputError, OpenCASCADE's
//          Standard_Failure or any std::exception in work, or a signal converted by OpenCASCADE);
//          "<what>: ... crashed (signal N ...)" when the child died; "<what>: ... took longer than
//          B s ..." when it ran out of time.
std::string run_isolated(const std::function<std::string()>& work, const std::string& what, double budget_seconds);

// The time budget for reading input: AUTOBLOCK_READ_TIMEOUT (seconds) if set to a number >= 0,
// else 30. 0 means: read in this process, without a child.
double read_budget_seconds();

}  // namespace autoblock
