// Writing text files atomically (see atomic_file.h): a failure or a kill never leaves a
// half-written file.
#pragma once

#include <string>

namespace autoblock {

// Inputs: path, text. Throws InputError when the folder is missing or the file cannot be written.
void write_text_file(const std::string& path, const std::string& text);

}  // namespace autoblock
