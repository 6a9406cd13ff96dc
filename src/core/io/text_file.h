// Writing text files atomically: a temporary file in the same folder renamed into place, so a
// failure never leaves a half-written file.
#pragma once

#include <string>

namespace autoblock {

// Inputs: path, text. Throws InputError when the folder is missing or the file cannot be written.
void write_text_file(const std::string& path, const std::string& text);

}  // namespace autoblock
