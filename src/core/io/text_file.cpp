#include "core/io/text_file.h"

#include <filesystem>
#include <fstream>
#include <random>

#include "core/common/error.h"

namespace autoblock {

void write_text_file(const std::string& path, const std::string& text) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path target(path);
  if (target.has_parent_path() && !fs::is_directory(target.parent_path(), ec)) {
    throw InputError(path + ": the folder " + target.parent_path().string() + " does not exist");
  }
  std::random_device random;
  const std::string temporary = path + ".tmp" + std::to_string(random());
  {
    std::ofstream out(temporary, std::ios::binary);
    out << text;
    out.close();
    if (!out) {
      fs::remove(temporary, ec);
      throw InputError(path + ": cannot write the file");
    }
  }
  fs::rename(temporary, path, ec);
  if (ec) {
    fs::remove(temporary, ec);
    throw InputError(path + ": cannot write the file");
  }
}

}  // namespace autoblock
