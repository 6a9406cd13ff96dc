#include "core/io/shape_file.h"

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>

#include "core/common/error.h"
#include "core/common/plugin.h"
#include "core/io/atomic_file.h"
#include "core/io/isolated_call.h"

namespace autoblock {
namespace {

namespace fs = std::filesystem;

// OpenCASCADE's readers print progress to stdout; the CLI's output is its own.
void silence_occt() {
  static std::once_flag once;
  std::call_once(once, [] {
    Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
  });
}

std::string lower_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// OpenCASCADE's BREP reader does not check its stream: on a malformed number or count it reads on
// from a failed stream, looping for ever or allocating without bound. A stream that throws on the
// first failed extraction stops it there.
TopoDS_Shape read_brep_stream(std::istream& in, std::string& why) {
  TopoDS_Shape shape;
  BRep_Builder builder;
  in.exceptions(std::ios::failbit | std::ios::badbit);
  try {
    BRepTools::Read(shape, in, builder);
  } catch (const std::ios_base::failure&) {
    shape.Nullify();
    why = "it ends early or holds a malformed number or count";
  } catch (const Standard_Failure& e) {
    shape.Nullify();
    why = std::string("OpenCASCADE: ") + e.GetMessageString();
  }
  if (shape.IsNull() && why.empty()) why = "no shape in it";
  return shape;
}

std::string brep_text_of(const TopoDS_Shape& shape) {
  std::ostringstream out;
  BRepTools::Write(shape, out);
  return out.str();
}

// The shape read by read, in a child process (isolated_call.h) unless the budget is 0; check runs
// there too. message: what the input is, for errors.
TopoDS_Shape read_isolated(const std::function<TopoDS_Shape()>& read, const ShapeCheck& check,
                           const std::string& message) {
  const double budget = read_budget_seconds();
  if (budget <= 0) {
    // In this process: the stream still fails loudly, and every failure becomes an input error.
    TopoDS_Shape shape;
    run_isolated(
        [&] {
          shape = read();
          if (check) check(shape);
          return std::string();
        },
        message, 0);
    return shape;
  }
  const std::string text = run_isolated(
      [&] {
        const TopoDS_Shape shape = read();
        if (check) check(shape);
        return brep_text_of(shape);
      },
      message, budget);
  // The child's BREP text was written by OpenCASCADE from a shape it read and checked.
  std::istringstream in(text);
  std::string why;
  TopoDS_Shape shape = read_brep_stream(in, why);
  if (shape.IsNull()) throw InputError(message + ": the shape read could not be passed back (" + why + ")");
  return shape;
}

TopoDS_Shape read_brep_or_throw(std::istream& in, const std::string& message) {
  std::string why;
  TopoDS_Shape shape = read_brep_stream(in, why);
  if (shape.IsNull()) throw InputError(message + " (" + why + ")");
  return shape;
}

// STEP goes through libautoblock_step.so (step_exchange.h), loaded now: a process that reads and
// writes only BREP never loads OpenCASCADE's STEP translator. (A read runs in a child process, so
// there only the child loads it.)
TopoDS_Shape read_step_or_throw(const std::string& path) {
  using Entry = void (*)(const std::string&, TopoDS_Shape&);
  auto entry = reinterpret_cast<Entry>(plugin_symbol("libautoblock_step.so", "autoblock_read_step_file", "AUTOBLOCK_STEP_LIBRARY"));
  TopoDS_Shape shape;
  entry(path, shape);
  return shape;
}

bool write_step(const TopoDS_Shape& shape, const std::string& path) {
  using Entry = bool (*)(const TopoDS_Shape&, const std::string&);
  auto entry = reinterpret_cast<Entry>(plugin_symbol("libautoblock_step.so", "autoblock_write_step_file", "AUTOBLOCK_STEP_LIBRARY"));
  return entry(shape, path);
}

}  // namespace

TopoDS_Shape read_shape_file(const std::string& path, const ShapeCheck& check) {
  silence_occt();
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path + ": no such file");
  if (fs::is_directory(path, ec)) throw InputError(path + ": is a directory, not a file");
  const std::string ext = lower_extension(path);
  if (ext != ".brep" && ext != ".brp" && ext != ".step" && ext != ".stp") {
    throw InputError(path + ": unknown file type '" + ext + "' (expected .brep, .step or .stp)");
  }
  if (!std::ifstream(path, std::ios::binary)) throw InputError(path + ": cannot open the file for reading");
  if (fs::file_size(path, ec) == 0) throw InputError(path + ": the file is empty");
  if (ext == ".brep" || ext == ".brp") {
    return read_isolated(
        [&] {
          std::ifstream in(path, std::ios::binary);
          return read_brep_or_throw(in, path + ": not a readable BREP file");
        },
        check, path);
  }
  return read_isolated([&] { return read_step_or_throw(path); }, check, path);
}

TopoDS_Shape read_brep_text(const std::string& text, const ShapeCheck& check) {
  silence_occt();
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) throw InputError("the BREP text is empty");
  return read_isolated(
      [&] {
        std::istringstream in(text);
        return read_brep_or_throw(in, "the text is not readable BREP");
      },
      check, "the BREP text");
}

void write_shape_file(const std::string& path, const TopoDS_Shape& shape) {
  silence_occt();
  const std::string ext = lower_extension(path);
  if (ext != ".brep" && ext != ".brp" && ext != ".step" && ext != ".stp") {
    throw InputError(path + ": unknown output file type '" + ext + "' (expected .brep, .step or .stp)");
  }
  write_file_atomically(path, [&](const std::string& temporary) {
    try {
      if (ext == ".brep" || ext == ".brp") return static_cast<bool>(BRepTools::Write(shape, temporary.c_str()));
      return write_step(shape, temporary);
    } catch (const Standard_Failure&) {
      return false;
    }
  });
}

std::string write_brep_text(const TopoDS_Shape& shape) { return brep_text_of(shape); }

}  // namespace autoblock
