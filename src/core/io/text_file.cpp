#include "core/io/text_file.h"

#include <fstream>

#include "core/io/atomic_file.h"

namespace autoblock {

void write_text_file(const std::string& path, const std::string& text) {
  write_file_atomically(path, [&](const std::string& temporary) {
    std::ofstream out(temporary, std::ios::binary);
    out << text;
    out.close();
    return static_cast<bool>(out);
  });
}

}  // namespace autoblock
