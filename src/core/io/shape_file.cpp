#include "core/io/shape_file.h"

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
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
#include <random>
#include <sstream>

#include "core/common/error.h"

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

std::string type_name(TopAbs_ShapeEnum type) {
  switch (type) {
    case TopAbs_COMPOUND: return "compound";
    case TopAbs_COMPSOLID: return "composite solid";
    case TopAbs_SOLID: return "solid";
    case TopAbs_SHELL: return "shell";
    case TopAbs_FACE: return "face";
    case TopAbs_WIRE: return "wire";
    case TopAbs_EDGE: return "edge";
    case TopAbs_VERTEX: return "vertex";
    default: return "shape";
  }
}

TopoDS_Shape read_brep_stream(std::istream& in) {
  TopoDS_Shape shape;
  BRep_Builder builder;
  try {
    BRepTools::Read(shape, in, builder);
  } catch (const Standard_Failure&) {
    shape.Nullify();
  }
  return shape;
}

}  // namespace

TopoDS_Shape read_shape_file(const std::string& path) {
  silence_occt();
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path + ": no such file");
  if (fs::is_directory(path, ec)) throw InputError(path + ": is a directory, not a file");
  const std::string ext = lower_extension(path);
  if (ext != ".brep" && ext != ".brp" && ext != ".step" && ext != ".stp") {
    throw InputError(path + ": unknown file type '" + ext + "' (expected .brep, .step or .stp)");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the file for reading");
  if (fs::file_size(path, ec) == 0) throw InputError(path + ": the file is empty");
  TopoDS_Shape shape;
  if (ext == ".brep" || ext == ".brp") {
    shape = read_brep_stream(in);
    if (shape.IsNull()) throw InputError(path + ": not a readable BREP file");
  } else {
    STEPControl_Reader reader;
    IFSelect_ReturnStatus status = IFSelect_RetFail;
    try {
      status = reader.ReadFile(path.c_str());
      if (status == IFSelect_RetDone) {
        reader.TransferRoots();
        shape = reader.OneShape();
      }
    } catch (const Standard_Failure&) {
      status = IFSelect_RetFail;
    }
    if (status != IFSelect_RetDone) throw InputError(path + ": not a readable STEP file");
    if (shape.IsNull()) throw InputError(path + ": the STEP file holds no shape");
  }
  return shape;
}

TopoDS_Shape read_brep_text(const std::string& text) {
  silence_occt();
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) throw InputError("the BREP text is empty");
  std::istringstream in(text);
  TopoDS_Shape shape = read_brep_stream(in);
  if (shape.IsNull()) throw InputError("the text is not readable BREP");
  return shape;
}

TopoDS_Face single_face(const TopoDS_Shape& shape, const std::string& what) {
  if (shape.IsNull()) throw InputError(what + " holds no shape");
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  if (faces.Extent() == 1) return TopoDS::Face(faces(1));
  const std::string kind = type_name(shape.ShapeType());
  if (faces.Extent() == 0) {
    throw InputError(what + " holds a " + kind + " with no face; expected exactly one planar face");
  }
  throw InputError(what + " holds a " + kind + " with " + std::to_string(faces.Extent()) +
                   " faces; expected exactly one planar face");
}

void write_shape_file(const std::string& path, const TopoDS_Shape& shape) {
  silence_occt();
  const std::string ext = lower_extension(path);
  if (ext != ".brep" && ext != ".brp" && ext != ".step" && ext != ".stp") {
    throw InputError(path + ": unknown output file type '" + ext + "' (expected .brep, .step or .stp)");
  }
  std::error_code ec;
  const fs::path target(path);
  if (target.has_parent_path() && !fs::is_directory(target.parent_path(), ec)) {
    throw InputError(path + ": the folder " + target.parent_path().string() + " does not exist");
  }
  std::random_device random;
  const std::string temporary = path + ".tmp" + std::to_string(random()) + ext;
  bool written = false;
  try {
    if (ext == ".brep" || ext == ".brp") {
      written = BRepTools::Write(shape, temporary.c_str());
    } else {
      STEPControl_Writer writer;
      written = writer.Transfer(shape, STEPControl_AsIs) == IFSelect_RetDone &&
                writer.Write(temporary.c_str()) == IFSelect_RetDone;
    }
  } catch (const Standard_Failure&) {
    written = false;
  }
  if (!written || (fs::rename(temporary, path, ec), ec)) {
    fs::remove(temporary, ec);
    throw InputError(path + ": cannot write the file");
  }
}

std::string write_brep_text(const TopoDS_Shape& shape) {
  std::ostringstream out;
  BRepTools::Write(shape, out);
  return out.str();
}

}  // namespace autoblock
