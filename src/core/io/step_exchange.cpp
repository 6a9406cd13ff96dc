#include "core/io/step_exchange.h"

#include <IFSelect_ReturnStatus.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <Standard_Failure.hxx>

#include "core/common/error.h"

namespace autoblock {

TopoDS_Shape read_step_file(const std::string& path) {
  STEPControl_Reader reader;
  IFSelect_ReturnStatus status = IFSelect_RetFail;
  TopoDS_Shape shape;
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
  return shape;
}

bool write_step_file(const TopoDS_Shape& shape, const std::string& path) {
  try {
    STEPControl_Writer writer;
    return writer.Transfer(shape, STEPControl_AsIs) == IFSelect_RetDone && writer.Write(path.c_str()) == IFSelect_RetDone;
  } catch (const Standard_Failure&) {
    return false;
  }
}

}  // namespace autoblock

// The entry points libautoblock_step.so exports for shape_file.cpp, which loads it on first use.
extern "C" __attribute__((visibility("default"))) void autoblock_read_step_file(const std::string& path,
                                                                               TopoDS_Shape& shape) {
  shape = autoblock::read_step_file(path);
}

extern "C" __attribute__((visibility("default"))) bool autoblock_write_step_file(const TopoDS_Shape& shape,
                                                                                const std::string& path) {
  return autoblock::write_step_file(shape, path);
}
